#include "planner/floor_view.h"

#include <algorithm>

namespace mhd {

namespace {

/// Where `disc` is at `now_s`, as a keep-out of `radius_m` grown for the unknown.
KeepOut seen_now(KeepOutKind kind, const TrackedDisc& disc, double now_s, double radius_m, double period_s) noexcept {
  const double age_s = std::max(0.0, now_s - disc.t_s);
  return KeepOut{kind, disc.p_W + age_s * disc.v_W, radius_m + (0.5 * age_s + period_s) * disc.v_W.norm()};
}

}  // namespace

FloorKeepOuts floor_keep_outs(const FloorView& view, double now_s, double stale_after_s,
                              const PlannerSettings& settings) noexcept {
  FloorKeepOuts out;
  const std::size_t count = std::min(view.count, kMaxOtherRigs);
  for (std::size_t i = 0; i < count; ++i) {
    const OtherRigTrack& rig = view.rigs[i];
    for (const TrackedDisc* disc : {&rig.user, &rig.base}) {
      if (!disc->known || !(now_s - disc->t_s <= stale_after_s)) out.current = false;
    }
    if (rig.user.known)
      out.keep_outs.add(
          seen_now(KeepOutKind::User, rig.user, now_s, settings.human_radius_m, settings.command_period_s));
    if (rig.base.known)
      out.keep_outs.add(
          seen_now(KeepOutKind::Base, rig.base, now_s, settings.robot_radius_m, settings.command_period_s));
  }
  return out;
}

}  // namespace mhd
