#include "dynamics/body_shape.h"

#include <LinearMath/btConvexHullComputer.h>

#include <stdexcept>

namespace mhd {

BodyHull make_body_hull(const TriangleMesh& mesh) {
  if (mesh.vertices_m.size() < 4) throw std::invalid_argument("a pushable object's mesh needs a volume");
  Eigen::Vector3d lo = mesh.vertices_m.front(), hi = lo;
  for (const Eigen::Vector3d& p : mesh.vertices_m) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d size_m = hi - lo;
  if (!(size_m.minCoeff() > 0.0)) throw std::invalid_argument("a pushable object's mesh is flat: it has no volume");
  BodyHull hull;
  hull.p_O_centre_m = 0.5 * (lo + hi);
  // A thin object gets a thinner margin (at most a quarter of its thickness).
  const double margin_m = std::min(kMaxBodyMargin_m, 0.125 * size_m.minCoeff());
  btConvexHullComputer computer;
  const double shrunk_m = computer.compute(mesh.vertices_m.front().data(), static_cast<int>(sizeof(Eigen::Vector3d)),
                                           static_cast<int>(mesh.vertices_m.size()), margin_m, 0.5);
  if (computer.vertices.size() < 4) throw std::invalid_argument("a pushable object's convex hull has no volume");
  hull.shape = std::make_unique<btConvexHullShape>();
  const btVector3 c(hull.p_O_centre_m.x(), hull.p_O_centre_m.y(), hull.p_O_centre_m.z());
  for (int i = 0; i < computer.vertices.size(); ++i) hull.shape->addPoint(computer.vertices[i] - c, false);
  hull.shape->recalcLocalAabb();
  hull.shape->setMargin(shrunk_m > 0.0 ? shrunk_m : 0.0);
  return hull;
}

StaticMeshShape make_static_mesh_shape(std::shared_ptr<const MeshBvh> bvh) {
  StaticMeshShape s;
  s.bvh = std::move(bvh);
  const double to_m = 1.0 / s.bvh->bvh_scale();
  // Bullet's API is not const; contact queries only read the tree and the mesh.
  auto* tree = const_cast<btBvhTriangleMeshShape*>(&s.bvh->shape());  // NOLINT
  s.shape = std::make_unique<btScaledBvhTriangleMeshShape>(tree, btVector3(to_m, to_m, to_m));
  return s;
}

}  // namespace mhd
