#include "haptic_server/base_command_scheduler.h"

namespace mhd {

bool BaseCommandScheduler::is_stop(const BaseTwist& twist_B) noexcept {
  return twist_B.vx_mps == 0.0 && twist_B.vz_mps == 0.0 && twist_B.omega_radps == 0.0;
}

bool BaseCommandScheduler::should_send(double t_s, bool new_plan, const BaseTwist& twist_B) const noexcept {
  const bool due = t_s - last_write_t_s_ >= base_period_s_;
  const bool must_stop_now = is_stop(twist_B) && !last_write_was_stop_;
  return new_plan || due || must_stop_now;
}

void BaseCommandScheduler::sent(double t_s, const BaseTwist& twist_B) noexcept {
  last_write_t_s_ = t_s;
  last_write_was_stop_ = is_stop(twist_B);
}

}  // namespace mhd
