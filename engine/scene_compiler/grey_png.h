#pragma once
// Reads a PNG as a greyscale image for height-map textures (docs/textures.md).

#include "material/haptic_texture.h"

#include <filesystem>
#include <string>

namespace mhd {

/// Most pixels a height map may have (2048 x 2048): a texture's memory, 24 bytes a pixel.
inline constexpr long kMaxHeightMapPixels = 2048L * 2048L;

/// Reads `file` into `image`: 8-bit grey per pixel, scaled to [0, 1] (0 black, 1 white).
/// Colour images become their luminance and alpha is dropped (libpng's simplified API).
/// Returns "" on success, else why not ("cannot read PNG '<file>': <libpng's reason>", or
/// that it has more than kMaxHeightMapPixels pixels); `image` is then unchanged.
[[nodiscard]] std::string read_grey_png(const std::filesystem::path& file, GreyImage& image);

}  // namespace mhd
