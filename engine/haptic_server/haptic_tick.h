#pragma once
// One tick of the haptic loop, free of threads and plugins so that it can be tested and
// benchmarked alone (the server's 1 kHz thread calls it):
//   tool position in the device frame + predicted base pose -> HIP in the world (Rig) ->
//   god-object proxy -> force -> safety (clamp, stale fade, jump fade) -> the force in the
//   device frame (a Cartesian device, ABI 3, maps it to its motors itself).
// On a desktop rig (Rig::desktop) the base pose is fixed and there is no tracker: tick()
// renders every tick with BasePose{} and no stale fade. A rig with a lift (Rig::lift)
// places the arm at the lift height the base last reported (set_lift_m); until the first
// report the arm's place is unknown, as before the first base pose.
// Base poses arrive from the tracker (~100-190 Hz) as base-sensor measurements and the
// commanded base twist from the planner (10 Hz); between them BasePosePredictor gives a
// pose for every tick, so the HIP does not leap when a sample arrives.
// A scene that shares objects with other rigs (<sharing>) runs its part of the sharing
// protocol in the tick (RigSharing): replicas posed before the objects move, the force
// from a stale replica faded before safety, the other rigs' pushes held and this tick's
// states and pushes put in its outbox after the reaction. receive_link() hands it what
// the link brought.
// tick() allocates nothing.

#include "kinematics/base_pose.h"
#include "kinematics/rig.h"
#include "prediction/base_pose_predictor.h"
#include "proxy/god_object.h"
#include "proxy/moving_world.h"
#include "proxy/proxy_look_ahead.h"
#include "safety/force_safety.h"
#include "scene_compiler/compiled_scene.h"
#include "sharing/rig_sharing.h"

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <optional>

namespace mhd {

struct HapticTickSettings {
  ForceSafetySettings safety;
  BasePosePredictorSettings prediction;
  /// false: use the newest measured base pose as is (what the thesis did; for comparison).
  bool predict_base_pose = true;
};

struct HapticTickOutput {
  double t_s = 0.0;
  Eigen::Vector3d p_D_tool_m = Eigen::Vector3d::Zero();  ///< what the device reported, in its frame
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy_W_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_W_N = Eigen::Vector3d::Zero();  ///< after safety: what the device gets
  Eigen::Vector3d proxy_force_W_N = Eigen::Vector3d::Zero();  ///< before safety
  Eigen::Vector3d force_D_N = Eigen::Vector3d::Zero();  ///< force_W_N in the device frame: what is sent
  BasePose base;  ///< the base pose this tick used
  double lift_m = 0.0;  ///< the lift height this tick used (0 without a lift; NaN: not known yet)
  /// The first shared object's origin as this tick rendered it (NaN: the scene shares none).
  Eigen::Vector3d p_W_shared_m = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  double tracker_age_s = 0.0;  ///< HapticTick::kNoTracker (NaN) on a desktop rig
  double safety_gain = 0.0;
  int contact_object = -1;
  bool in_contact = false;
  bool startup = false;  ///< no base pose yet (start-up): no HIP, no force; neither stale nor a fault
  bool stale = false;
  bool jump = false;
  bool clamped = false;
  bool hip_inside_object = false;  ///< the proxy waits (no force) for the HIP to leave an object
  bool proxy_budget_exhausted = false;  ///< the proxy hit its per-tick work budget (ProxyOutput)
};

class HapticTick {
 public:
  /// The tracker age of a desktop rig, which has none: render() treats it as fresh.
  static constexpr double kNoTracker = std::numeric_limits<double>::quiet_NaN();

  /// `scene` must outlive this object.
  HapticTick(const CompiledScene& scene, const Rig& rig, const HapticTickSettings& settings);

  /// A base-sensor pose from the tracker (X_is900_base_sensor), measured at t_s.
  BaseSampleStatus add_base_sensor_sample(double t_s, const Pose& X_is900_base_sensor) noexcept;
  /// The base twist the planner commanded at t_s.
  void add_base_command(double t_s, const BaseTwist& twist_B) noexcept;
  /// The lift height the base last reported (NaN: none yet). Ignored on a rig without a lift.
  void set_lift_m(double lift_m) noexcept;

  /// The tick at t_s with the device's tool position in its frame; dt_s is the time since
  /// the last tick. A non-finite position gives zero force (and counts as a fault).
  HapticTickOutput tick(double t_s, double dt_s, const Eigen::Vector3d& p_D_tool_m) noexcept;

  /// The tick's second half, with the base pose and tracker age given instead of
  /// predicted: HIP, proxy, safety and the device's force. tick() is render() with the predictor's
  /// pose; replay calls it with a recording's. `base` empty: no base pose known yet.
  HapticTickOutput render(double t_s, double dt_s, const Eigen::Vector3d& p_D_tool_m, const std::optional<BasePose>& base,
                          double tracker_age_s) noexcept;

  /// Between ticks, after the last tick's force has gone to the device: steps a copy of the
  /// proxy to where the HIP will be next (ProxyLookAhead), so the next tick finds its data in
  /// the cache. Changes nothing any tick returns. Does nothing (ran false) unless the last
  /// tick rendered a proxy.
  LookAheadReport look_ahead() noexcept;

  [[nodiscard]] const ForceSafety& safety() const noexcept { return safety_; }
  /// Ticks with no base pose yet (before the first tracker sample): counted here, not by
  /// the safety stage, so a normal start is not reported as stale or faulty.
  [[nodiscard]] std::uint64_t startup_ticks() const noexcept { return startup_ticks_; }
  [[nodiscard]] const BasePosePredictor& predictor() const noexcept { return predictor_; }
  [[nodiscard]] const ProxyState& proxy_state() const noexcept { return proxy_; }
  /// The world as this tick's objects stand (moving objects at their poses of the last tick).
  [[nodiscard]] const CollisionWorld& world() const noexcept { return moving_.world(); }
  /// Ticks on which a moving object squeezed the proxy against another surface.
  [[nodiscard]] std::uint64_t squeeze_ticks() const noexcept { return squeeze_ticks_; }
  /// This rig's part in the objects it shares; null when the scene shares none.
  [[nodiscard]] RigSharing* sharing() noexcept { return sharing_ ? &*sharing_ : nullptr; }
  [[nodiscard]] const RigSharing* sharing() const noexcept { return sharing_ ? &*sharing_ : nullptr; }

 private:
  // render()'s steps.
  void move_objects(double t_s) noexcept;
  void render_hand(double dt_s, ForceSafetyInput& safety_in, HapticTickOutput& out) noexcept;
  void render_no_hand(bool base_known, ForceSafetyInput& safety_in, HapticTickOutput& out) noexcept;
  [[nodiscard]] Eigen::Vector3d shared_force_W(double t_s, double dt_s, const Eigen::Vector3d& force_W_N) noexcept;

  const CompiledScene& scene_;
  ProxySettings proxy_settings_;  // the scene's, clamped to the run's force limit
  Rig rig_;
  HapticTickSettings settings_;
  BasePosePredictor predictor_;
  ForceSafety safety_;
  ProxyState proxy_;
  ProxyLookAhead look_ahead_;
  double last_rendered_dt_s_ = 0.0;
  bool rendered_last_tick_ = false;  // the last tick stepped the proxy
  std::optional<RigSharing> sharing_;  // before moving_: it says which objects are replicas
  MovingWorld moving_;  // the scene's world, its moving objects where they are now
  std::optional<double> t0_s_;  // the first tick: scripted motions start there
  std::uint64_t squeeze_ticks_ = 0;
  bool has_measurement_ = false;
  std::uint64_t startup_ticks_ = 0;
  double last_measurement_t_s_ = 0.0;
  BasePose last_measurement_;
  double lift_m_ = 0.0;  ///< NaN on a rig with a lift until the base reports its height
};

}  // namespace mhd
