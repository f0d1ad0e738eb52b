#pragma once
// Which scene primitives the proxy touches as exact shapes, and as which.

#include "geometry/exact_shape.h"
#include "scene/scene_description.h"

#include <optional>

namespace mhd {

/// The exact shape a primitive asks for (`exact="true"`, the default for a capsule), in
/// the object's frame as CollisionWorld::set_exact_shape takes it; nullopt for a mesh or a
/// primitive rendered as its tessellation.
[[nodiscard]] std::optional<ExactShape> exact_shape_of(const ShapeSource& source);

}  // namespace mhd
