#pragma once
// Bullet collision shapes of a scene object's mesh, for the dynamics world: a pushable
// body is the convex hull of its mesh (shrunk by Bullet's margin, which adds it back, so
// the surface stays where the mesh is; edges rounded by the margin); a still object is
// its exact triangle mesh. Built at scene start, never on the haptic thread.

#include "collision/mesh_bvh.h"
#include "geometry/triangle_mesh.h"

#include <BulletCollision/CollisionShapes/btScaledBvhTriangleMeshShape.h>
#include <btBulletCollisionCommon.h>

#include <Eigen/Core>

#include <memory>

namespace mhd {

/// A body's hull, in the body frame B: the object's frame O moved to the centre of the
/// mesh's bounding box (where the body's mass is centred).
struct BodyHull {
  std::unique_ptr<btConvexHullShape> shape;
  Eigen::Vector3d p_O_centre_m = Eigen::Vector3d::Zero();  ///< origin of B in O
};

/// Largest collision margin of a body: Bullet's contacts are most robust with a margin,
/// and 2 mm rounds a hand-sized box's edges by less than a fingertip feels.
inline constexpr double kMaxBodyMargin_m = 2e-3;

/// The convex hull of `mesh`. Throws std::invalid_argument for a mesh with no volume.
[[nodiscard]] BodyHull make_body_hull(const TriangleMesh& mesh);

/// A still object's exact surface: the haptic tree itself, seen at metre scale (the tree
/// is in Bullet's units, MeshBvh::bvh_scale()). Shared, not copied or built again.
struct StaticMeshShape {
  std::shared_ptr<const MeshBvh> bvh;
  std::unique_ptr<btScaledBvhTriangleMeshShape> shape;
};

[[nodiscard]] StaticMeshShape make_static_mesh_shape(std::shared_ptr<const MeshBvh> bvh);

}  // namespace mhd
