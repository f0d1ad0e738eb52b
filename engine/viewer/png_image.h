#pragma once
// An 8-bit RGBA image, top row first, and PNG files through libpng.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mhd::viewer {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, row 0 at the top

  [[nodiscard]] const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
  }
};

/// Empty on success, else "cannot write PNG 'out.png': <reason>".
[[nodiscard]] std::string write_png(const std::filesystem::path& file, const RgbaImage& image);

/// Empty on success, else "cannot read PNG 'x.png': <reason>".
[[nodiscard]] std::string read_png(const std::filesystem::path& file, RgbaImage& image);

}  // namespace mhd::viewer
