#include "haptic_server/haptic_tick.h"

#include "collision/point_containment.h"

#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace mhd {
namespace {

std::optional<RigSharing> sharing_of(const CompiledScene& scene) {
  if (!scene.sharing) return std::nullopt;
  return std::optional<RigSharing>(std::in_place, scene.sharing->rig_id, scene.sharing->objects, scene.world);
}

// The scene's objects; those another rig holds are driven (replicas), out of the physics.
MovingWorld moving_world_of(const CompiledScene& scene, const std::optional<RigSharing>& sharing) {
  if (!sharing) return MovingWorld(scene.world, scene.motions, scene.dynamics);
  const std::size_t n = scene.dynamics.size();
  const std::vector<char> replica = sharing->replicas(n);
  std::vector<std::optional<ObjectDynamics>> dynamics = scene.dynamics;
  const auto driven = std::make_unique<bool[]>(n);
  for (std::size_t i = 0; i < n; ++i) {
    driven[i] = replica[i] != 0;
    if (driven[i]) dynamics[i].reset();
  }
  return MovingWorld(scene.world, scene.motions, dynamics, std::span<const bool>(driven.get(), n));
}

}  // namespace

HapticTick::HapticTick(const CompiledScene& scene, const Rig& rig, const HapticTickSettings& settings)
    : scene_(scene),
      proxy_settings_(scene.proxy),
      rig_(rig),
      settings_(settings),
      predictor_(settings.prediction),
      safety_(settings.safety),
      sharing_(sharing_of(scene)),
      moving_(moving_world_of(scene, sharing_)) {
  // One force limit: the safety stage's, which the server set from the device.
  proxy_settings_.max_force_N = settings.safety.max_force_N;
  if (rig_.lift()) lift_m_ = std::numeric_limits<double>::quiet_NaN();
}

void HapticTick::set_lift_m(double lift_m) noexcept {
  if (rig_.lift()) lift_m_ = lift_m;
}

BaseSampleStatus HapticTick::add_base_sensor_sample(double t_s, const Pose& X_is900_base_sensor) noexcept {
  const BasePose pose = rig_.base_from_sensor(X_is900_base_sensor);
  const BaseSampleStatus status = predictor_.add_measurement(t_s, pose);
  if (status == BaseSampleStatus::Accepted || status == BaseSampleStatus::Reset) {
    has_measurement_ = true;
    last_measurement_t_s_ = t_s;
    last_measurement_ = pose;
  }
  return status;
}

void HapticTick::add_base_command(double t_s, const BaseTwist& twist_B) noexcept {
  (void)predictor_.add_command(t_s, twist_B);
}

HapticTickOutput HapticTick::tick(double t_s, double dt_s, const Eigen::Vector3d& p_D_tool_m) noexcept {
  if (rig_.kind() == RigKind::Desktop) {
    // No tracker: the device frame is fixed (Rig::desktop), nothing can go stale.
    return render(t_s, dt_s, p_D_tool_m, BasePose{}, kNoTracker);
  }
  std::optional<BasePose> base;
  // Without the lift's height the arm's place is as unknown as without the base's pose.
  if (has_measurement_ && std::isfinite(lift_m_)) {
    base = settings_.predict_base_pose ? predictor_.predict(t_s) : last_measurement_;
  }
  return render(t_s, dt_s, p_D_tool_m, base, predictor_.age_s(t_s));
}

HapticTickOutput HapticTick::render(double t_s, double dt_s, const Eigen::Vector3d& p_D_tool_m,
                                    const std::optional<BasePose>& base, double tracker_age_s) noexcept {
  HapticTickOutput out;
  rendered_last_tick_ = false;
  out.t_s = t_s;
  out.p_D_tool_m = p_D_tool_m;
  out.tracker_age_s = tracker_age_s;
  out.lift_m = lift_m_;

  ForceSafetyInput safety_in;
  safety_in.dt_s = dt_s;
  // Without a tracker the device's own reading is the whole pose: never stale.
  safety_in.tracker_age_s = std::isnan(tracker_age_s) ? 0.0 : tracker_age_s;

  if (sharing_) sharing_->before_move(t_s, moving_);
  move_objects(t_s);
  if (base.has_value() && p_D_tool_m.allFinite() && std::isfinite(lift_m_)) {
    out.base = *base;
    render_hand(dt_s, safety_in, out);
  } else {
    render_no_hand(base.has_value() && std::isfinite(lift_m_), safety_in, out);
  }
  // After the reaction went to the bodies: the other rigs' pushes, and what to send.
  if (sharing_) {
    sharing_->after_render(t_s, proxy_, out.force_W_N, moving_);
    if (sharing_->object_count() > 0) {
      out.p_W_shared_m = moving_.world().pose(sharing_->declaration(0).object).translation();
    }
  }
  return out;
}

void HapticTick::move_objects(double t_s) noexcept {
  // Objects move on their own clock from the first tick, whether or not a hand is known;
  // a proxy being rendered is carried by what moved.
  if (!t0_s_) t0_s_ = t_s;
  if (moving_.moves() && std::isfinite(t_s)) {
    if (moving_.advance(t_s - *t0_s_, proxy_, proxy_settings_.skin_m).squeezed) ++squeeze_ticks_;
  }
}

void HapticTick::render_hand(double dt_s, ForceSafetyInput& safety_in, HapticTickOutput& out) noexcept {
  const Pose X_W_robot = rig_.X_W_robot_from_base(out.base);
  out.p_W_hip = rig_.p_W_from_device(X_W_robot, out.p_D_tool_m, out.lift_m);
  if (!proxy_.initialised) {
    // The proxy starts only with the hand in free space: started inside an object it
    // would render the object inside out and pull the hand in. Until then, no force.
    if (point_inside_surface(moving_.world(), out.p_W_hip)) {
      out.hip_inside_object = true;
      out.proxy_W_m = out.p_W_hip;
      safety_in.force_W_N.setConstant(std::numeric_limits<double>::quiet_NaN());  // no force known
      (void)safety_.apply(safety_in);  // zero force; the fade-in starts once the proxy does
      moving_.apply_reaction(proxy_, Eigen::Vector3d::Zero());
      return;
    }
    reset_proxy(proxy_, out.p_W_hip);
  }
  const ProxyOutput p =
      step_proxy(moving_.world(), scene_.materials, proxy_settings_, proxy_, out.p_W_hip, dt_s, moving_.twists());
  rendered_last_tick_ = true;
  last_rendered_dt_s_ = dt_s;
  out.proxy_W_m = p.proxy_W;
  out.proxy_force_W_N = p.force_W;
  out.in_contact = p.in_contact;
  out.contact_object = p.contact_object;
  out.proxy_budget_exhausted = p.budget_exhausted;
  safety_in.force_W_N = sharing_ ? shared_force_W(out.t_s, dt_s, p.force_W) : p.force_W;
  safety_in.p_W_hip = out.p_W_hip;
  const ForceSafetyOutput s = safety_.apply(safety_in);
  out.force_W_N = s.force_W_N;
  out.safety_gain = s.gain;
  out.stale = s.stale;
  out.jump = s.jump;
  out.clamped = s.clamped;
  out.force_D_N = rig_.force_P_from_W(X_W_robot, out.force_W_N);  // the lift only translates
  if (!out.force_D_N.allFinite()) out.force_D_N.setZero();
  // The bodies the proxy touches are pushed back by what the hand is sent to feel.
  moving_.apply_reaction(proxy_, out.force_W_N);
}

void HapticTick::render_no_hand(bool base_known, ForceSafetyInput& safety_in, HapticTickOutput& out) noexcept {
  if (!base_known && out.p_D_tool_m.allFinite()) {
    // Start-up: no base pose yet, so no HIP and no force. Normal, not a fault; the safety
    // stage starts from zero gain when the first pose arrives.
    ++startup_ticks_;
    safety_.reset();
    out.startup = true;
  } else {
    // The device gave no position: nothing is known, nothing is pushed; a fault.
    safety_in.force_W_N.setConstant(std::numeric_limits<double>::quiet_NaN());
    safety_in.p_W_hip.setConstant(std::numeric_limits<double>::quiet_NaN());
    out.stale = safety_.apply(safety_in).stale;
  }
  out.p_W_hip.setConstant(std::numeric_limits<double>::quiet_NaN());
  out.proxy_W_m = out.p_W_hip;
  moving_.apply_reaction(proxy_, Eigen::Vector3d::Zero());  // no hand: nothing pushes
}

Eigen::Vector3d HapticTick::shared_force_W(double t_s, double dt_s, const Eigen::Vector3d& force_W_N) noexcept {
  // The force from a replica whose states stopped coming fades (ReplicaFade).
  return force_W_N * sharing_->force_gain(t_s, dt_s, proxy_, force_W_N);
}

LookAheadReport HapticTick::look_ahead() noexcept {
  if (!rendered_last_tick_) return {};
  return look_ahead_.run(moving_.world(), scene_.materials, proxy_settings_, proxy_, last_rendered_dt_s_,
                         moving_.twists());
}

}  // namespace mhd
