#pragma once
// The haptic side of `mhd try`: the engine's god-object proxy (step_proxy, the same call
// as `mhd proxy-replay`) on the scene's compiled collision world and materials, stepped
// at 1 kHz of simulated time. Each drawn frame advances a frame's worth of ticks while
// the HIP moves in a straight line from where the last tick left it to where the mouse
// put it, so a fast hand passes through every tick between and, the proxy's sweeps being
// crossing-free, cannot tunnel through a surface. No plugins, no threads, no devices.

#include "proxy/god_object.h"
#include "proxy/moving_world.h"
#include "scene_compiler/compiled_scene.h"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace mhd::viewer {

/// What the hand would feel after the last tick.
struct HandSample {
  double t_s = 0.0;  ///< simulated time of the last tick
  long ticks = 0;
  Eigen::Vector3d p_W_hip_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_W_proxy_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_W_N = Eigen::Vector3d::Zero();  ///< on the hand, clamped to the scene's max force
  bool in_contact = false;
  /// HIP to proxy distance in contact (the depth of the HIP under the surface), else 0.
  double penetration_m = 0.0;
  int contact_object = -1;  ///< index of the touched object, -1 without contact
};

class HandSimulation {
 public:
  static constexpr double kTick_s = 1e-3;

  /// Why the proxy cannot start at p_W_start_m (inside an object, on a surface), or nullopt.
  [[nodiscard]] static std::optional<std::string> start_blocked(const CompiledScene& scene,
                                                                const Eigen::Vector3d& p_W_start_m);

  /// Precondition: start_blocked(scene, p_W_start_m) is nullopt. `scene` must outlive this.
  HandSimulation(const CompiledScene& scene, const Eigen::Vector3d& p_W_start_m);

  /// Advances dt_s of simulated time in whole ticks (the remainder carries over), the HIP
  /// moving linearly to p_W_hip_m over them. A dt_s shorter than a tick may step none.
  const HandSample& advance(const Eigen::Vector3d& p_W_hip_m, double dt_s);

  [[nodiscard]] const HandSample& sample() const { return sample_; }
  /// The scene's objects where they are after the last tick (moving objects move with
  /// simulated time, from 0 at the start).
  [[nodiscard]] const CollisionWorld& world() const { return moving_.world(); }

 private:
  const CompiledScene& scene_;
  ProxyState state_;
  MovingWorld moving_;
  HandSample sample_;
  double owed_s_ = 0.0;  ///< simulated time not yet stepped (less than a tick)
};

}  // namespace mhd::viewer
