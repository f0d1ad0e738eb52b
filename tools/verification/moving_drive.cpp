#include "verification/moving_drive.h"

#include "proxy/moving_world.h"
#include "verification/surface_crossing_oracle.h"

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
  const auto n_objects = static_cast<std::size_t>(w.object_count());
  std::vector<SurfaceCrossingOracle> oracles;  // each object in its own frame
  oracles.reserve(n_objects);
  for (std::size_t o = 0; o < n_objects; ++o) oracles.emplace_back(w.shape(static_cast<int>(o)).mesh());
  const auto X_OW = [&](std::size_t o) { return w.pose(static_cast<int>(o)).inverse(Eigen::Isometry); };
  // Whether a world segment, in the objects' current poses, touches any of them.
  const auto touches = [&](const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) {
    for (std::size_t o = 0; o < n_objects; ++o) {
      const Pose X = X_OW(o);
      if (oracles[o].segment_touches_surface(X * a_W, X * b_W)) return true;
    }
    return false;
  };

  const double dt_s = 1.0 / rate_Hz;
  ProxyState state;
  reset_proxy(state, hip_path_W.front());
  std::vector<Pose> X_OW_before(n_objects);
  d.out.reserve(hip_path_W.size());
  for (std::size_t k = 1; k < hip_path_W.size(); ++k) {
    const Eigen::Vector3d& hip_W = hip_path_W[k];
    for (std::size_t o = 0; o < n_objects; ++o) X_OW_before[o] = X_OW(o);
    const Eigen::Vector3d p_before_W = state.proxy_W;
    const CarryOutput carry = moving.advance(static_cast<double>(k) * dt_s, state, settings.skin_m);
    const Eigen::Vector3d p_carried_W = state.proxy_W;
    const ProxyOutput out = step_proxy(w, materials, settings, state, hip_W, dt_s, moving.twists());
    moving.apply_reaction(state, out.force_W);
    ++d.ticks;
    d.pushes += carry.pushed > 0 ? 1 : 0;
    d.squeezes += carry.squeezed ? 1 : 0;
    d.contact_ticks += out.in_contact ? 1 : 0;

    bool crossed = false;
    bool inside = false;
    for (std::size_t o = 0; o < n_objects && !crossed; ++o) {
      const Pose X = X_OW(o);
      crossed = oracles[o].segment_touches_surface(X_OW_before[o] * p_before_W, X * p_carried_W);
      for (int i = 0; i + 1 < state.path_points && !crossed; ++i) {
        crossed = oracles[o].segment_touches_surface(X * state.path_W[static_cast<std::size_t>(i)],
                                                     X * state.path_W[static_cast<std::size_t>(i + 1)]);
      }
      inside = inside || oracles[o].point_inside_closed_mesh(X * out.proxy_W);
    }
    d.crossings += crossed ? 1 : 0;
    d.inside += inside ? 1 : 0;
    const double gap_m = (out.proxy_W - hip_W).norm();
    if (gap_m > kMovingFollowTolerance_m) {
      if (!touches(p_carried_W, hip_W)) ++d.not_followed;
      if (out.force_W.norm() > 0.0 && !touches(out.proxy_W, hip_W)) ++d.free_force;
    }
    d.out.push_back(out);
    auto& poses = d.X_WO.emplace_back(n_objects);
    for (std::size_t o = 0; o < n_objects; ++o) poses[o] = w.pose(static_cast<int>(o));
  }
  return d;
}

}  // namespace mhd::verify
