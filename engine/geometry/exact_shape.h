#pragma once
// A convex primitive that the collision layer sweeps as the shape it is, not as the
// triangles of its tessellation (docs/proxy.md, "Exact primitives"). Only the shape and
// its size, in its object's frame; the queries live with their users (engine/collision
// for the sweeps, tools/verification for the independent oracle).
//
// Sphere, capsule, cylinder and box are centred on the object's origin; the capsule's and
// the cylinder's axis is z. The half-space is z <= 0: its surface is the infinite plane
// z = 0, its outward normal +z (a floor).

#include <Eigen/Core>

namespace mhd {

enum class ExactKind { Sphere, Capsule, Cylinder, Box, HalfSpace };

struct ExactShape {
  ExactKind kind = ExactKind::Sphere;
  /// Sphere, capsule and cylinder.
  double radius_m = 0.0;
  /// Capsule: half the length of its axis segment (caps not included); cylinder: half its height.
  double half_height_m = 0.0;
  /// Box: half its size along x, y, z.
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
};

}  // namespace mhd
