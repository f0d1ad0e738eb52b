#pragma once
// The thesis's planner (ch. 3.3-3.5 and 3.8; Table 3.1 as reconstructed in docs/planner.md):
//   if d < robot radius + human radius      escape: goal on the ray from the user through
//                                           the base at d' (pi' = 0), full speed
//   else if angle(base, target) < pi'       straight to the target
//   else                                    sub-target: the base's direction from the user
//                                           turned by pi' towards the target, at d'
// Speed: v_max, falling in proportion to the distance within the deceleration interval;
// 0 within the stop interval of the target. Turn rate likewise towards facing the user from
// the current position (eq. 3.1). Acts once the HIP leaves the usable workspace (or the
// base is within the safety band) and until it has stopped at the target facing the user.

#include "planner/planner.h"

namespace mhd {

class SeedPlanner final : public Planner {
 public:
  explicit SeedPlanner(const PlannerSettings& settings) : Planner(settings) {}
  [[nodiscard]] PlannerKind kind() const noexcept override { return PlannerKind::Seed; }

 private:
  [[nodiscard]] PlannerOutput plan(const PlannerInput& input) noexcept override;
};

}  // namespace mhd
