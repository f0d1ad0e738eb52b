#pragma once
// A small world for the proxy's tests: meshes added with a material, the HIP stepped or
// moved in a straight line at 1 kHz. Shared by god_object_test and proxy_contract_test.

#include "proxy/god_object.h"

#include <Eigen/Core>

#include <memory>
#include <utility>
#include <vector>

namespace mhd::test {

inline constexpr double kProxyTestDt_s = 1e-3;

inline std::shared_ptr<const MeshBvh> shape_of(TriangleMesh mesh) {
  compute_vertex_normals(mesh);
  return std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(std::move(mesh)));
}

/// Quad with corners a, b, c, d (CCW seen from the side it faces).
inline TriangleMesh quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                         const Eigen::Vector3d& d) {
  TriangleMesh m;
  m.vertices_m = {a, b, c, d};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

inline HapticMaterial stiff(double k_N_per_m) {
  HapticMaterial m;
  m.stiffness_N_per_m = k_N_per_m;
  return m;
}

struct ProxyRig {
  CollisionWorld world;
  std::vector<HapticMaterial> materials;
  ProxySettings settings;
  ProxyState state;

  void add(TriangleMesh mesh, const HapticMaterial& mat = stiff(1000.0), const Pose& X_WO = Pose::Identity()) {
    world.add_object(shape_of(std::move(mesh)), X_WO);
    materials.push_back(mat);
  }
  ProxyOutput step(const Eigen::Vector3d& p_W_hip) {
    return step_proxy(world, materials, settings, state, p_W_hip, kProxyTestDt_s);
  }
  /// Moves the HIP in a straight line with `steps` ticks; returns the last tick's output.
  ProxyOutput move(const Eigen::Vector3d& from_W, const Eigen::Vector3d& to_W, int steps) {
    ProxyOutput out;
    for (int i = 1; i <= steps; ++i) out = step(from_W + (to_W - from_W) * (double(i) / steps));
    return out;
  }
};

}  // namespace mhd::test
