#include "sharing/object_authority.h"

#include <cmath>

namespace mhd {

namespace {

bool is_rotation(const Eigen::Matrix3d& R) noexcept {
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 && R.determinant() > 0.0;
}

bool finite(const SharedObjectState& s) noexcept {
  return std::isfinite(s.t_s) && s.X_WO.matrix().allFinite() && s.twist_W.v_W_origin_mps.allFinite() &&
         s.twist_W.omega_W_radps.allFinite() && is_rotation(s.X_WO.linear());
}

}  // namespace

const char* to_string(StateVerdict v) noexcept {
  switch (v) {
    case StateVerdict::Obeyed: return "obeyed";
    case StateVerdict::NotShared: return "not_shared";
    case StateVerdict::NotFinite: return "not_finite";
    case StateVerdict::OldTerm: return "old_term";
    case StateVerdict::NotAuthority: return "not_authority";
    case StateVerdict::NotAllowed: return "not_allowed";
    case StateVerdict::Stale: return "stale";
  }
  return "unknown";
}

bool ObjectAuthority::share(int object, const std::uint32_t* rigs, int rig_count) noexcept {
  if (object < 0 || object >= kMaxSharedObjects || rigs == nullptr || rig_count < 1 || rig_count > kMaxAuthorityRigs) {
    return false;
  }
  for (int i = 0; i < rig_count; ++i) {
    for (int j = 0; j < i; ++j) {
      if (rigs[i] == rigs[j]) return false;
    }
  }
  Entry e;
  e.shared = true;
  for (int i = 0; i < rig_count; ++i) e.rigs[static_cast<std::size_t>(i)] = rigs[i];
  e.rig_count = rig_count;
  e.authority = rigs[0];
  entries_[static_cast<std::size_t>(object)] = e;
  return true;
}

bool ObjectAuthority::is_shared(int object) const noexcept {
  return object >= 0 && object < kMaxSharedObjects && entries_[static_cast<std::size_t>(object)].shared;
}

std::uint32_t ObjectAuthority::authority(int object) const noexcept {
  return entries_[static_cast<std::size_t>(object)].authority;
}

std::uint32_t ObjectAuthority::epoch(int object) const noexcept { return entries_[static_cast<std::size_t>(object)].epoch; }

bool ObjectAuthority::may_hold(const Entry& e, std::uint32_t rig) noexcept {
  for (int i = 0; i < e.rig_count; ++i) {
    if (e.rigs[static_cast<std::size_t>(i)] == rig) return true;
  }
  return false;
}

std::int64_t ObjectAuthority::take_over(int object, std::uint32_t rig) noexcept {
  if (!is_shared(object)) return -1;
  Entry& e = entries_[static_cast<std::size_t>(object)];
  if (!may_hold(e, rig)) return -1;
  e.authority = rig;
  e.epoch += 1;
  e.heard = false;
  e.last_sequence = 0;
  return e.epoch;
}

StateVerdict ObjectAuthority::judge(const SharedObjectState& state) noexcept {
  const auto verdict = [&]() noexcept {
    if (!is_shared(state.object)) return StateVerdict::NotShared;
    if (!finite(state)) return StateVerdict::NotFinite;
    Entry& e = entries_[static_cast<std::size_t>(state.object)];
    if (state.epoch < e.epoch) return StateVerdict::OldTerm;
    if (state.epoch > e.epoch) {
      if (!may_hold(e, state.authority_rig)) return StateVerdict::NotAllowed;
      e.epoch = state.epoch;
      e.authority = state.authority_rig;
      e.heard = true;
      e.last_sequence = state.sequence;
      return StateVerdict::Obeyed;
    }
    if (state.authority_rig != e.authority) return StateVerdict::NotAuthority;
    if (e.heard && state.sequence <= e.last_sequence) return StateVerdict::Stale;
    e.heard = true;
    e.last_sequence = state.sequence;
    return StateVerdict::Obeyed;
  }();
  ++counts_[static_cast<std::size_t>(verdict)];
  return verdict;
}

}  // namespace mhd
