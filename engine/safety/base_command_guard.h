#pragma once
// The last stage before a velocity command reaches the mobile base, for every planner and
// every backend. Every input carries its age, and the guard acts on fresh data only:
//  - the command is zero while the base pose or the head pose is older than
//    tracker_timeout_s (or was never measured), or when anything in it is not finite;
//  - the keep-out zone around the user grows with what the ages leave unknown: the user may
//    have walked user_max_speed_mps x (head age + command hold) since the head sample, the
//    base max_speed_mps x (base age + command hold). Inside keep_out_m plus that margin,
//    no velocity points at any place the user may be (the cone of the uncertainty disk);
//  - after a stop, the speed limits grow from zero at resume_accel_mps2 and
//    resume_angular_accel_radps2 (a slow command passes almost at once, a fast one ramps);
//  - the command is scaled (direction kept) into the base's speed and turn-rate limits.
// apply() is noexcept and allocation-free; it counts stops by cause (a stop is one
// episode of zero commands for one cause) and keep-out deflections.

#include "kinematics/base_pose.h"

#include <Eigen/Core>

#include <cstdint>
#include <limits>

namespace mhd {

struct BaseCommandGuardSettings {
  double max_speed_mps = 0.5;
  double max_omega_radps = 0.6981317007977318;  ///< 40 deg/s
  double tracker_timeout_s = 0.05;  ///< older base or head poses stop the base
  /// Distance between base centre and user centre (robot radius + human radius) inside
  /// which the base may only move away from the user.
  double keep_out_m = 0.475;
  double user_max_speed_mps = 1.5;  ///< how fast the user may walk unseen (simulated user's maximum)
  double command_hold_s = 0.001;    ///< how long one command is held (the io period)
  /// After a stop the limits grow back from zero at these rates (full speed in 0.5 s).
  double resume_accel_mps2 = 1.0;
  double resume_angular_accel_radps2 = 1.3962634015954636;  ///< 80 deg/s^2
};

/// What the guard judges one command on; ages in seconds, +inf when never measured.
struct BaseGuardInput {
  double t_s = 0.0;
  BasePose X_WB;  ///< the base pose (planar)
  double base_age_s = std::numeric_limits<double>::infinity();
  Eigen::Vector2d p_W_head_xz_m = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  double head_age_s = std::numeric_limits<double>::infinity();
};

enum class BaseGuardAction { Passed, Scaled, Stopped, Deflected };
enum class BaseStopCause { None, NotFinite, BaseStale, HeadStale };

struct BaseGuardDecision {
  BaseTwist twist_B;
  BaseGuardAction action = BaseGuardAction::Passed;
  BaseStopCause stop_cause = BaseStopCause::None;
};

/// Stop episodes by cause, and commands the keep-out changed.
struct BaseStopCounts {
  std::uint64_t head_stale = 0;
  std::uint64_t base_stale = 0;
  std::uint64_t not_finite = 0;
  std::uint64_t keep_out_deflections = 0;
  [[nodiscard]] std::uint64_t stops() const noexcept { return head_stale + base_stale + not_finite; }
};

class BaseCommandGuard {
 public:
  explicit BaseCommandGuard(const BaseCommandGuardSettings& settings = {}) noexcept;

  [[nodiscard]] BaseGuardDecision apply(const BaseTwist& command_B, const BaseGuardInput& input) noexcept;

  [[nodiscard]] const BaseCommandGuardSettings& settings() const noexcept { return settings_; }
  [[nodiscard]] const BaseStopCounts& counts() const noexcept { return counts_; }

 private:
  [[nodiscard]] BaseStopCause stop_cause(const BaseTwist& command_B, const BaseGuardInput& input) const noexcept;
  /// Removes motion towards the user's uncertainty disk; true when something was removed.
  [[nodiscard]] bool keep_out(BaseTwist& t, const BaseGuardInput& input) const noexcept;

  BaseCommandGuardSettings settings_;
  BaseStopCounts counts_;
  BaseStopCause previous_cause_ = BaseStopCause::None;
  double resume_start_s_ = -std::numeric_limits<double>::infinity();
};

}  // namespace mhd
