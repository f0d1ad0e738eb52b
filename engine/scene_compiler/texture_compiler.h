#pragma once
// Builds a material's texture from what the scene says (docs/textures.md): procedural
// textures from their parameters, height maps from their PNG.

#include "material/haptic_texture.h"

#include <memory>
#include <string>

namespace mhd {

/// Sets `texture` to the texture `spec` describes and returns "", or returns why it cannot
/// be built (a value outside what the scene reader accepts, for descriptions built in code;
/// an image that cannot be read) and leaves `texture` unchanged.
[[nodiscard]] std::string compile_texture(const HapticTextureSpec& spec, std::shared_ptr<const HapticTexture>& texture);

}  // namespace mhd
