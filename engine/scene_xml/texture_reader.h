#pragma once
// Reads a material's <texture> element (docs/scene-format.md, docs/textures.md) into a
// HapticTextureSpec. Every problem is reported against the file and line it is on.

#include "material/haptic_texture.h"
#include "scene_xml/diagnostic_sink.h"

#include <optional>

namespace tinyxml2 {
class XMLElement;
}  // namespace tinyxml2

namespace mhd::scene_xml {

/// The texture `e` describes, or nullopt when anything in it is wrong (each fault reported
/// to `sink`). An image file is resolved against the folder of the file `sink` reads and
/// must be a readable regular file; it is not decoded here (the scene compiler does).
[[nodiscard]] std::optional<HapticTextureSpec> read_texture(const tinyxml2::XMLElement& e, const DiagnosticSink& sink);

}  // namespace mhd::scene_xml
