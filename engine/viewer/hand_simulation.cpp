#include "viewer/hand_simulation.h"

#include "proxy/proxy_start.h"

#include <cmath>

namespace mhd::viewer {

std::optional<std::string> HandSimulation::start_blocked(const CompiledScene& scene,
                                                         const Eigen::Vector3d& p_W_start_m) {
  return proxy_start_blocked(scene.world, p_W_start_m, scene.proxy.skin_m);
}

HandSimulation::HandSimulation(const CompiledScene& scene, const Eigen::Vector3d& p_W_start_m)
    : scene_(scene), moving_(scene.world, scene.motions, scene.dynamics) {
  moving_.place(0.0);
  reset_proxy(state_, p_W_start_m);
  sample_.p_W_hip_m = p_W_start_m;
  sample_.p_W_proxy_m = p_W_start_m;
}

const HandSample& HandSimulation::advance(const Eigen::Vector3d& p_W_hip_m, double dt_s) {
  owed_s_ += dt_s;
  // The small epsilon keeps 1/60 s frames from losing a tick to rounding now and then.
  const long ticks = static_cast<long>(std::floor(owed_s_ / kTick_s + 1e-9));
  if (ticks <= 0) return sample_;
  owed_s_ -= static_cast<double>(ticks) * kTick_s;
  const Eigen::Vector3d p_W_from_m = sample_.p_W_hip_m;
  for (long i = 1; i <= ticks; ++i) {
    const double a = static_cast<double>(i) / static_cast<double>(ticks);
    const Eigen::Vector3d p_W_tick_m = p_W_from_m + a * (p_W_hip_m - p_W_from_m);
    (void)moving_.advance(static_cast<double>(sample_.ticks + i) * kTick_s, state_, scene_.proxy.skin_m);
    const ProxyOutput out =
        step_proxy(moving_.world(), scene_.materials, scene_.proxy, state_, p_W_tick_m, kTick_s, moving_.twists());
    moving_.apply_reaction(state_, out.force_W);  // a pushable object is pushed back
    sample_.p_W_hip_m = p_W_tick_m;
    sample_.p_W_proxy_m = out.proxy_W;
    sample_.force_W_N = out.force_W;
    sample_.in_contact = out.in_contact;
    sample_.contact_object = out.contact_object;
  }
  sample_.ticks += ticks;
  sample_.t_s = static_cast<double>(sample_.ticks) * kTick_s;
  sample_.penetration_m = sample_.in_contact ? (sample_.p_W_hip_m - sample_.p_W_proxy_m).norm() : 0.0;
  return sample_;
}

}  // namespace mhd::viewer
