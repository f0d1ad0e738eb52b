#pragma once
// Reads <sharing rig_id="N"> and its <shared_object object="NAME" id="I" rigs="A B"/>
// (docs/shared-objects.md, docs/scene-format.md "Shared objects"), and checks them
// against the whole scene once every file is read. Every problem is reported against the
// file and line it is on.

#include "scene/scene_description.h"
#include "scene_xml/diagnostic_sink.h"

#include <optional>

namespace tinyxml2 {
class XMLElement;
}  // namespace tinyxml2

namespace mhd::scene_xml {

/// Highest rig id a scene takes (the dds plugins' other_rigs: 1000 R + S stays 32-bit).
inline constexpr int kMaxRigId = 999999;
/// Most rigs one object's authority may pass between.
inline constexpr int kMaxSharingRigs = 8;
/// Most objects one scene shares.
inline constexpr int kMaxSceneSharedObjects = 32;

/// The <sharing> `e` describes; each fault reported to `sink` (what is read despite it is
/// kept, so that later checks still run).
[[nodiscard]] SharingDescription read_sharing(const tinyxml2::XMLElement& e, const DiagnosticSink& sink);

/// What the scene as a whole must hold for its <sharing>: each shared object exists and
/// is pushable (<dynamics>), is shared once, with an id of its own, and lists this rig.
[[nodiscard]] Diagnostics check_sharing(const SceneDescription& scene);

}  // namespace mhd::scene_xml
