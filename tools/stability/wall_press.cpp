#include "wall_press.h"

#include "kinematics/phantom_kinematics.h"
#include "proxy/god_object.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace mhd::stability {
namespace {

/// A horizontal square wall (normal +y) of half-size 0.5 m whose top is at p_W.
std::shared_ptr<const MeshBvh> wall_at(const Eigen::Vector3d& p_W) {
  auto mesh = std::make_shared<TriangleMesh>();
  const double h = 0.5;
  mesh->vertices_m = {p_W + Eigen::Vector3d(-h, 0, h), p_W + Eigen::Vector3d(h, 0, h), p_W + Eigen::Vector3d(h, 0, -h),
                      p_W + Eigen::Vector3d(-h, 0, -h)};
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  compute_vertex_normals(*mesh);
  return std::make_shared<MeshBvh>(std::move(mesh));
}

struct Window {
  double low = 0.0, high = 0.0, sum = 0.0;
  int count = 0;
  void add(double v) {
    low = count == 0 ? v : std::min(low, v);
    high = count == 0 ? v : std::max(high, v);
    sum += v;
    ++count;
  }
  [[nodiscard]] double ptp() const { return high - low; }
};

}  // namespace

WallPressFigures press_wall(const WallPressSettings& s) {
  sim_phantom::PhantomSimConfig config;
  config.hand_model = sim_phantom::HandModel::Impedance;
  config.hand_impedance = s.hand;
  config.position_resolution_m = s.position_resolution_m;
  sim_phantom::PhantomSimModel device(config);
  const BasePose base;
  const Eigen::Isometry3d X_W_P = device.X_W_phantom(base);
  const Eigen::Vector3d surface_W = X_W_P * config.device.workspace.center_P_m();

  CollisionWorld world;
  world.add_object(wall_at(surface_W), Pose::Identity());
  HapticMaterial material;
  material.stiffness_N_per_m = s.wall_stiffness_N_per_m;
  material.damping_Ns_per_m = s.wall_damping_Ns_per_m;
  const std::vector<HapticMaterial> materials{material};
  ProxySettings proxy_settings;
  proxy_settings.max_force_N = config.max_force_N;
  ProxyState proxy;

  // The user's hand comes down from 5 mm above at 0.05 m/s and then means to stay
  // press_depth_m below the surface.
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  auto intended_W = [&](double t_s) {
    return surface_W + up * std::max(0.005 - 0.05 * t_s, -s.press_depth_m);
  };

  const double T = 1.0 / s.rate_hz;
  const auto ticks = static_cast<long>(std::llround(s.duration_s * s.rate_hz));
  const auto window_ticks = static_cast<long>(std::llround(s.window_s * s.rate_hz));
  device.start(0.0);
  device.simulate_until(0.0, base, intended_W(0.0));
  reset_proxy(proxy, X_W_P * device.p_P_hip_m());
  WallPressFigures result;
  Window previous, last;
  for (long k = 0; k <= ticks; ++k) {
    const double t_s = static_cast<double>(k) * T;
    device.simulate_until(t_s, base, intended_W(t_s));
    const Eigen::Vector3d p_W_hip = X_W_P * device.p_P_hip_m();
    const ProxyOutput out = step_proxy(world, materials, proxy_settings, proxy, p_W_hip, T);
    const Eigen::Vector3d F_P = X_W_P.linear().transpose() * out.force_W;
    device.command(phantom_joint_torques(config.device.geometry, device.joint_angles_rad(), F_P), t_s);
    const double normal_force_N = out.force_W.dot(up);
    result.max_force_N = std::max(result.max_force_N, out.force_W.norm());
    if (k > ticks - window_ticks) {
      last.add(normal_force_N);
    } else if (k > ticks - 2 * window_ticks) {
      previous.add(normal_force_N);
    }
  }
  result.force_ptp_previous_N = previous.ptp();
  result.force_ptp_last_N = last.ptp();
  result.mean_force_last_N = last.count > 0 ? last.sum / last.count : 0.0;
  result.stable = result.force_ptp_last_N < 1e-3 || result.force_ptp_last_N < 0.9 * result.force_ptp_previous_N;
  return result;
}

double passivity_bound_N_per_m(double physical_damping_Ns_per_m, double wall_damping_Ns_per_m, double period_s) {
  return 2.0 * (physical_damping_Ns_per_m - std::abs(wall_damping_Ns_per_m)) / period_s;
}

double highest_stable_stiffness_N_per_m(WallPressSettings settings, double low_N_per_m, double high_N_per_m,
                                        int iterations) {
  for (int i = 0; i < iterations; ++i) {
    const double middle = std::sqrt(low_N_per_m * high_N_per_m);
    settings.wall_stiffness_N_per_m = middle;
    (press_wall(settings).stable ? low_N_per_m : high_N_per_m) = middle;
  }
  return low_N_per_m;
}

}  // namespace mhd::stability
