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

StaticMeshShape make_static_mesh_shape(std::shared_ptr<const TriangleMesh> mesh) {
  StaticMeshShape s;
  s.mesh = std::move(mesh);
  const TriangleMesh& m = *s.mesh;
  if (m.triangles.empty()) throw std::invalid_argument("a still object's mesh has no triangles");
  // Bullet reads the mesh's own arrays (indices as int: a mesh has far fewer than 2^31 vertices).
  s.triangles = std::make_unique<btTriangleIndexVertexArray>(
      static_cast<int>(m.triangles.size()),
      const_cast<int*>(reinterpret_cast<const int*>(m.triangles.data())),  // NOLINT: Bullet's API is not const
      static_cast<int>(sizeof(TriangleIndices)), static_cast<int>(m.vertices_m.size()),
      const_cast<btScalar*>(m.vertices_m.front().data()), static_cast<int>(sizeof(Eigen::Vector3d)));
  s.shape = std::make_unique<btBvhTriangleMeshShape>(s.triangles.get(), true);
  return s;
}

}  // namespace mhd
