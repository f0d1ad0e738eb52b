#pragma once
// Reads an object's <dynamics mass_kg="..." friction="..."/> (docs/scene-format.md
// "Pushable objects"): the object becomes a rigid body the hand can push. Every problem
// is reported against the file and line it is on.

#include "geometry/object_dynamics.h"
#include "scene_xml/diagnostic_sink.h"

#include <optional>

namespace tinyxml2 {
class XMLElement;
}  // namespace tinyxml2

namespace mhd::scene_xml {

/// Friction with still objects when <dynamics> names none: a cardboard box on a wooden floor.
inline constexpr double kDefaultBodyFriction = 0.5;

/// The dynamics `e` describes, or nullopt when anything in it is wrong (each fault
/// reported to `sink`): mass_kg is required, positive and finite; friction optional,
/// finite and >= 0.
[[nodiscard]] std::optional<ObjectDynamics> read_dynamics(const tinyxml2::XMLElement& e, const DiagnosticSink& sink);

}  // namespace mhd::scene_xml
