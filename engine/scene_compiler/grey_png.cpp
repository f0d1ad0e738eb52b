#include "scene_compiler/grey_png.h"

#include <png.h>

#include <fmt/format.h>

#include <cstdint>
#include <vector>

namespace mhd {

std::string read_grey_png(const std::filesystem::path& file, GreyImage& image) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&png, file.c_str()) == 0) {
    std::string reason = png.message;
    png_image_free(&png);
    return fmt::format("cannot read PNG '{}': {}", file.string(), reason);
  }
  const long pixels = static_cast<long>(png.width) * static_cast<long>(png.height);
  if (pixels > kMaxHeightMapPixels) {
    png_image_free(&png);
    return fmt::format("PNG '{}' is {} x {} pixels; a height map may have at most {} (2048 x 2048)", file.string(),
                       png.width, png.height, kMaxHeightMapPixels);
  }
  png.format = PNG_FORMAT_GRAY;
  std::vector<std::uint8_t> grey(PNG_IMAGE_SIZE(png));
  if (png_image_finish_read(&png, nullptr, grey.data(), 0, nullptr) == 0) {
    std::string reason = png.message;
    png_image_free(&png);
    return fmt::format("cannot read PNG '{}': {}", file.string(), reason);
  }
  GreyImage out;
  out.width = static_cast<int>(png.width);
  out.height = static_cast<int>(png.height);
  out.grey.reserve(grey.size());
  for (const std::uint8_t g : grey) out.grey.push_back(g / 255.0);
  image = std::move(out);
  return {};
}

}  // namespace mhd
