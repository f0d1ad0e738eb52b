#include "dds_common/tracker_subscriber.h"

#include "dds_common/dds_convert.h"

#include <algorithm>

namespace mhd::dds {
namespace {
constexpr std::size_t kPendingCapacity = 256;
}

TrackerSubscriber::TrackerSubscriber(const Participant& participant, const TrackerValidationLimits& limits)
    : subscriber_(participant, rig_partition(limits.rig_id)), validator_(limits), peers_(participant) {
  pending_.reserve(kPendingCapacity);
}

std::size_t TrackerSubscriber::poll(std::span<mhd_tracker_sample> out, double host_now_s, std::int64_t now_ns) {
  for (;;) {
    const std::span<const mhd_dds_TrackerSample> taken = subscriber_.reader().take();
    for (const mhd_dds_TrackerSample& s : taken) {
      if (validator_.check(s, now_ns)) continue;
      if (pending_.size() == kPendingCapacity) pending_.erase(pending_.begin());
      pending_.push_back(s);
    }
    if (taken.empty()) break;
  }
  // What waited here since an earlier call may have aged past max_age_s.
  std::erase_if(pending_, [&](const mhd_dds_TrackerSample& s) { return validator_.expired(s, now_ns); });
  const std::size_t n = std::min(out.size(), pending_.size());
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = from_dds(pending_[i], host_from_realtime(pending_[i].timestamp_ns, host_now_s, now_ns));
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
  return n;
}

}  // namespace mhd::dds
