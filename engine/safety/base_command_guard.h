#pragma once
// The last stage before a velocity command reaches the mobile base, for every planner and
// every backend: a command is zero while tracking is stale or when anything in it is not
// finite; it is scaled (direction kept) into the base's speed and turn-rate limits; and the
// part of its velocity that points at the user is removed while the base is closer to the
// user than keep_out_m, so the base never drives into the person beside it.

#include "kinematics/base_pose.h"

#include <Eigen/Core>

#include <cstdint>

namespace mhd {

struct BaseCommandGuardSettings {
  double max_speed_mps = 0.5;
  double max_omega_radps = 0.6981317007977318;  ///< 40 deg/s
  double tracker_timeout_s = 0.05;  ///< older base or head poses stop the base
  /// Distance between base centre and user centre (robot radius + human radius) inside
  /// which the base may only move away from the user.
  double keep_out_m = 0.475;
};

enum class BaseGuardAction { Passed, Scaled, Stopped, Deflected };

struct BaseGuardResult {
  BaseTwist twist_B;
  BaseGuardAction action = BaseGuardAction::Passed;
};

class BaseCommandGuard {
 public:
  explicit BaseCommandGuard(const BaseCommandGuardSettings& settings = {}) noexcept;

  /// `user_xz_W` may be non-finite (no user known): no keep-out check then.
  [[nodiscard]] BaseGuardResult apply(const BaseTwist& command_B, const BasePose& base, const Eigen::Vector2d& user_xz_W,
                                      double tracker_age_s) noexcept;

  [[nodiscard]] const BaseCommandGuardSettings& settings() const noexcept { return settings_; }
  [[nodiscard]] std::uint64_t stops() const noexcept { return stops_; }
  [[nodiscard]] std::uint64_t deflections() const noexcept { return deflections_; }

 private:
  BaseCommandGuardSettings settings_;
  std::uint64_t stops_ = 0;
  std::uint64_t deflections_ = 0;
};

}  // namespace mhd
