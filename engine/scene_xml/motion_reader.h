#pragma once
// Reads an object's <motion> (docs/scene-format.md "Moving objects"): keyframed poses
// (<key> children, repeat="hold|loop|pingpong") or a constant twist from the object's
// <pose> (velocity, angular_velocity_deg_s attributes). Every problem is reported against
// the file and line it is on.

#include "geometry/object_motion.h"
#include "scene_xml/diagnostic_sink.h"

#include <optional>

namespace tinyxml2 {
class XMLElement;
}  // namespace tinyxml2

namespace mhd::scene_xml {

/// Fastest object motion a scene may script: faster than this a surface moves more than
/// 2 mm (or a 0.5 m object's rim 6 mm) per 1 kHz tick, beyond what a hand can follow.
inline constexpr double kMaxObjectSpeed_mps = 2.0;
inline constexpr double kMaxObjectRate_deg_s = 720.0;
/// Bounded memory for hostile files.
inline constexpr int kMaxMotionKeys = 100'000;

/// The motion `e` describes, or nullopt when anything in it is wrong (each fault reported
/// to `sink`). `X_WO` is the object's <pose>, where a twist starts; `pose_given` says
/// whether the object has one (keyframes take their poses from their keys, and refuse one).
[[nodiscard]] std::optional<ObjectMotion> read_motion(const tinyxml2::XMLElement& e, const DiagnosticSink& sink,
                                                      double unit_to_m, const Pose& X_WO, bool pose_given);

}  // namespace mhd::scene_xml
