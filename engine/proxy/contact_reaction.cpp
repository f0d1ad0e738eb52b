#include "proxy/contact_reaction.h"

#include <algorithm>

namespace mhd {

ContactReactions contact_reactions(const ProxyState& state, const Eigen::Vector3d& force_W_N) noexcept {
  ContactReactions r;
  const int n = std::clamp(state.plane_count, 0, kMaxConstraintPlanes);
  if (n == 0 || !force_W_N.allFinite() || force_W_N.squaredNorm() == 0.0) return r;
  std::array<double, kMaxConstraintPlanes> load{};
  double total = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    load[k] = std::max(0.0, force_W_N.dot(state.planes[k].normal_W));
    total += load[k];
  }
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    // No plane loaded (the force along them all): shared equally.
    const double share = total > 0.0 ? load[k] / total : 1.0 / n;
    if (share == 0.0) continue;
    const int object = state.planes[k].triangle.object;
    int slot = 0;
    while (slot < r.count && r.on[static_cast<std::size_t>(slot)].object != object) ++slot;
    if (slot == r.count) r.on[static_cast<std::size_t>(r.count++)].object = object;
    r.on[static_cast<std::size_t>(slot)].f_W_N -= share * force_W_N;
  }
  return r;
}

}  // namespace mhd
