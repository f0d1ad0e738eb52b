#pragma once
// The haptic server's end of the tracker link: takes tracker samples from DDS without
// blocking, validates them (sample_validation.h) and hands out the accepted ones as the
// ABI's mhd_tracker_sample with host-clock timestamps. Used by the `dds` tracker plugin.

#include "dds_common/dds_topics.h"
#include "dds_common/peer_watch.h"
#include "dds_common/security_refusal_log.h"
#include "dds_common/sample_validation.h"

#include <mhd/plugin_abi.h>

#include <cstddef>
#include <span>
#include <vector>

namespace mhd::dds {

class TrackerSubscriber {
 public:
  /// Reads rig limits.rig_id's partition. `participant` must outlive this.
  TrackerSubscriber(const Participant& participant, const TrackerValidationLimits& limits);

  /// Takes what DDS has, validates it at `now_ns` and writes up to out.size() accepted
  /// samples, oldest first, stamped on the host clock (`host_now_s` read with now_ns).
  /// Accepted samples that do not fit wait for the next call (up to 256, then the
  /// oldest are lost), and are dropped as stale once older than max_age_s. Never blocks.
  std::size_t poll(std::span<mhd_tracker_sample> out, double host_now_s, std::int64_t now_ns);
  /// Blocks until samples arrive or timeout_ns passes; true at once when accepted
  /// samples still wait for poll().
  bool wait(dds_duration_t timeout_ns) { return !pending_.empty() || subscriber_.reader().wait(timeout_ns); }

  [[nodiscard]] const DropCounts& counts() const { return validator_.counts(); }
  [[nodiscard]] std::uint32_t matched_writers() const { return subscriber_.reader().matched_writers(); }
  /// Writers matched now and ever: under DDS Security a refused writer never matches,
  /// so total_count counts only the writers the rig accepted (docs/networking.md).
  [[nodiscard]] dds_subscription_matched_status_t writer_matches() const {
    return subscriber_.reader().subscription_matched();
  }
  /// Remote participants heard, admitted and refused (peer_watch.h), as of `now_ns`.
  [[nodiscard]] PeerWatch::Counts peers(std::int64_t now_ns) { return peers_.counts(now_ns); }
  /// Refusals Cyclone logged in this process (security_refusal_log.h).
  [[nodiscard]] static std::uint64_t security_refusals() { return SecurityRefusalLog::refusals(); }

 private:
  Subscriber<mhd_dds_TrackerSample> subscriber_;
  TrackerSampleValidator validator_;
  std::vector<mhd_dds_TrackerSample> pending_;  ///< accepted, not yet handed out
  SecurityRefusalLog refusal_log_;
  PeerWatch peers_;
};

}  // namespace mhd::dds
