#pragma once
// Who knocked on a participant's door, and who was let in (docs/networking.md,
// "Counting refusals"). Cyclone 0.10 has no status for a peer that DDS Security
// refuses, so MHD counts refusals from what it does show:
// - its DCPSParticipant builtin topic lists every remote participant heard, refused or
//   not (checked on Cyclone 0.10.2: an unauthenticated one and one with forged
//   permissions both appear);
// - with discovery protection (our governance), a peer's endpoints appear in
//   DCPSPublication / DCPSSubscription only once it is authenticated and permitted.
// A peer heard for longer than a grace period without one visible endpoint is counted
// as refused. Every MHD process has endpoints, so an admitted MHD peer never counts.
// The builtin topics are read when the counts are asked for, on the caller's thread, not
// in Cyclone's listener threads: those synchronise through Cyclone's own locks, which a
// thread checker cannot see (it reported our mutex as raced). When a peer was first heard
// is its announcement's source timestamp (never later than now), so the grace does not
// depend on how often the counts are read.

#include "dds_common/dds_entity.h"

#include <dds/dds.h>

#include <array>
#include <cstdint>
#include <map>
#include <mutex>

namespace mhd::dds {

class PeerWatch {
 public:
  struct Counts {
    std::uint32_t heard = 0;     ///< remote participants heard of, ever
    std::uint32_t admitted = 0;  ///< of these, with an endpoint visible to us
    std::uint32_t refused = 0;   ///< heard for longer than the grace, no endpoint visible
  };

  /// Watches `participant`'s discovery (it must outlive this).
  explicit PeerWatch(const Participant& participant, std::int64_t grace_ns = 2'000'000'000);
  PeerWatch(const PeerWatch&) = delete;
  PeerWatch& operator=(const PeerWatch&) = delete;
  ~PeerWatch();

  /// Reads what discovery has heard since the last call and returns the counts as of
  /// `now_ns` (dds_time() clock), this participant itself left out. Any thread; calls are
  /// serialised.
  [[nodiscard]] Counts counts(std::int64_t now_ns);

 private:
  struct Peer {
    std::int64_t first_heard_ns = -1;  ///< -1: known only from an endpoint so far
    bool has_endpoint = false;
  };
  void take(dds_entity_t reader, bool endpoints, std::int64_t now_ns);

  std::int64_t grace_ns_;
  dds_guid_t own_{};
  std::mutex mutex_;  // callers of counts(); never the haptic thread
  std::map<std::array<std::uint8_t, 16>, Peer> peers_;
  Entity participants_, publications_, subscriptions_;
};

}  // namespace mhd::dds
