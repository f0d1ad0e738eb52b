#include "sharing/remote_pushes.h"

#include <cmath>

namespace mhd {

bool RemotePushes::receive(const SharedPush& push) noexcept {
  const bool finite = std::isfinite(push.t_s) && push.f_W_N.allFinite() && push.p_O_m.allFinite();
  if (!finite || push.object < 0) {
    ++refused_;
    return false;
  }
  for (int i = 0; i < count_; ++i) {
    SharedPush& kept = pushes_[static_cast<std::size_t>(i)];
    if (kept.object != push.object || kept.from_rig != push.from_rig) continue;
    if (push.sequence <= kept.sequence) {
      ++refused_;
      return false;
    }
    kept = push;
    return true;
  }
  if (count_ == kMaxRemotePushes) {
    ++refused_;
    return false;
  }
  pushes_[static_cast<std::size_t>(count_++)] = push;
  return true;
}

}  // namespace mhd
