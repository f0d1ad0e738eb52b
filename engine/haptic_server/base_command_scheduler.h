#pragma once
// When the io thread writes a base command (docs/haptic_server.md, "The base"): at the
// base rate, which also feeds the base's own command watchdog; at once when the planner
// has a new plan; and at once when the guard turns a moving command into a stop.

#include "kinematics/base_pose.h"

#include <limits>

namespace mhd {

class BaseCommandScheduler {
 public:
  /// `base_period_s`: one over the base rate (> 0).
  explicit BaseCommandScheduler(double base_period_s) noexcept : base_period_s_(base_period_s) {}

  /// Whether the guarded command `twist_B` should go out at host time `t_s`: true when a
  /// new plan has arrived, when a base period has passed since the last write (always
  /// before the first), or when `twist_B` is a stop and the last command written was not.
  /// Pure: no state changes.
  [[nodiscard]] bool should_send(double t_s, bool new_plan, const BaseTwist& twist_B) const noexcept;

  /// Notes that `twist_B` was written at `t_s` (call after a successful base_write).
  void sent(double t_s, const BaseTwist& twist_B) noexcept;

  /// A zero twist in all three components.
  [[nodiscard]] static bool is_stop(const BaseTwist& twist_B) noexcept;

 private:
  double base_period_s_;
  double last_write_t_s_ = -std::numeric_limits<double>::infinity();
  bool last_write_was_stop_ = false;
};

}  // namespace mhd
