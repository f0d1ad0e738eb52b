#include "verification/moving_drive.h"

#include "proxy/moving_world.h"

#include <algorithm>

namespace mhd::verify {

MovingDrive drive_moving_proxy(const CollisionWorld& world, std::span<const std::optional<ObjectMotion>> motions,
                               std::span<const HapticMaterial> materials, const ProxySettings& settings,
                               std::span<const Eigen::Vector3d> hip_path_W, double rate_Hz,
                               std::span<const std::optional<ObjectDynamics>> dynamics,
                               const RigidBodySettings& physics) {
  MovingDrive d;
  if (hip_path_W.empty()) return d;
  MovingWorld moving(world, std::vector<std::optional<ObjectMotion>>(motions.begin(), motions.end()), dynamics, physics);
  moving.place(0.0);
  const CollisionWorld& w = moving.world();
  MovingTickCheck check(w);
  const auto n_objects = static_cast<std::size_t>(w.object_count());

  const double dt_s = 1.0 / rate_Hz;
  ProxyState state;
  reset_proxy(state, hip_path_W.front());
  d.out.reserve(hip_path_W.size());
  for (std::size_t k = 1; k < hip_path_W.size(); ++k) {
    const Eigen::Vector3d& p_W_hip = hip_path_W[k];
    check.before_move(w);
    const Eigen::Vector3d p_before_W = state.proxy_W;
    const CarryOutput carry = moving.advance(static_cast<double>(k) * dt_s, state, settings.skin_m);
    const Eigen::Vector3d p_carried_W = state.proxy_W;
    const ProxyOutput out = step_proxy(w, materials, settings, state, p_W_hip, dt_s, moving.twists());
    moving.apply_reaction(state, out.force_W);
    ++d.ticks;
    d.pushes += carry.pushed > 0 ? 1 : 0;
    d.squeezes += carry.squeezed ? 1 : 0;
    d.contact_ticks += out.in_contact ? 1 : 0;
    const auto path_points = static_cast<std::size_t>(std::clamp(state.path_points, 0, kMaxProxyPath));
    const MovingTickVerdict v =
        check.judge(w, p_before_W, p_carried_W, std::span<const Eigen::Vector3d>(state.path_W.data(), path_points), out,
                    p_W_hip);
    d.crossings += v.crossed ? 1 : 0;
    d.inside += v.inside ? 1 : 0;
    d.not_followed += v.not_followed ? 1 : 0;
    d.free_force += v.free_force ? 1 : 0;
    d.out.push_back(out);
    auto& poses = d.X_WO.emplace_back(n_objects);
    for (std::size_t o = 0; o < n_objects; ++o) poses[o] = w.pose(static_cast<int>(o));
  }
  return d;
}

}  // namespace mhd::verify
