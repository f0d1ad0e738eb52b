#include "viewer/png_image.h"

#include <png.h>

#include <fmt/core.h>

namespace mhd::viewer {

std::string write_png(const std::filesystem::path& file, const RgbaImage& image) {
  const std::size_t expected = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() != expected) {
    return fmt::format("cannot write PNG '{}': the image is {}x{} with {} bytes", file.string(), image.width,
                       image.height, image.rgba.size());
  }
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGBA;
  if (png_image_write_to_file(&png, file.c_str(), 0, image.rgba.data(), 0, nullptr) == 0) {
    std::string reason = png.message;
    png_image_free(&png);
    return fmt::format("cannot write PNG '{}': {}", file.string(), reason);
  }
  return {};
}

std::string read_png(const std::filesystem::path& file, RgbaImage& image) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&png, file.c_str()) == 0) {
    std::string reason = png.message;
    png_image_free(&png);
    return fmt::format("cannot read PNG '{}': {}", file.string(), reason);
  }
  png.format = PNG_FORMAT_RGBA;
  RgbaImage out;
  out.width = static_cast<int>(png.width);
  out.height = static_cast<int>(png.height);
  out.rgba.resize(PNG_IMAGE_SIZE(png));
  if (png_image_finish_read(&png, nullptr, out.rgba.data(), 0, nullptr) == 0) {
    std::string reason = png.message;
    png_image_free(&png);
    return fmt::format("cannot read PNG '{}': {}", file.string(), reason);
  }
  image = std::move(out);
  return {};
}

}  // namespace mhd::viewer
