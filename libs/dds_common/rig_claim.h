#pragma once
// One haptic process per rig id (docs/networking.md, "One process per rig"). A process
// that publishes as rig N claims N on mhd_rig_claim (RigClaim, keyed by rig and
// claimant) and reads the other claims of N. The oldest live claim holds the rig: a
// younger claimant is refused, withdraws its claim and must never publish as N; the
// holder counts each claimant it refused, and writes its claim again naming the last
// one: a refused claim stays until its holder has named it (bounded by `settle_ns` when
// the process ends), so that a process refused and gone at once is still counted. A
// claim is not trusted until `settle_ns` after it was made (discovery must have had time
// to bring the older claims), so a refused process has published nothing. A claim lives
// as long as its process (liveliness), so a rig whose process died can be claimed again.

#include "dds_common/dds_topics.h"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

namespace mhd::dds {

struct Claimant {
  std::uint64_t host_id = 0;  ///< FNV-1a of the host name
  std::uint32_t pid = 0;
  std::string host;
  [[nodiscard]] std::string name() const { return host + ":" + std::to_string(pid); }
};

/// This process: its host name and pid.
[[nodiscard]] Claimant this_process();

class RigClaim {
 public:
  enum class Standing { Settling, Holding, Refused };

  /// Claims `rig_id` in its partition of `participant` (which must outlive this), made
  /// at claimed_ns on dds_time()'s clock. Throws DdsError (NOT_ALLOWED_BY_SECURITY when
  /// the identity may not claim this rig).
  RigClaim(const Participant& participant, std::uint32_t rig_id, std::int64_t settle_ns,
           Claimant self = this_process(), std::int64_t claimed_ns = realtime_ns());
  /// Withdraws the claim; a refused one its holder has not yet counted first waits for
  /// that, up to settle_ns.
  ~RigClaim();
  RigClaim(const RigClaim&) = delete;
  RigClaim& operator=(const RigClaim&) = delete;

  /// Reads the claims that arrived and says where this claim stands at now_ns. Refused
  /// is for good; the claim is withdrawn once the holder has counted it. Never blocks;
  /// not for a real-time thread.
  Standing update(std::int64_t now_ns);

  /// Younger claimants of this rig refused by this claim (each counted once); 0 once this
  /// claim is refused itself (an older one refused them).
  [[nodiscard]] std::uint64_t refused() const noexcept { return refused_self_ ? 0 : refused_; }
  /// Why this claim was refused: the rig, the holder and since when.
  [[nodiscard]] std::string refusal() const;
  [[nodiscard]] std::uint32_t rig_id() const noexcept { return rig_id_; }

 private:
  using Key = std::pair<std::uint64_t, std::uint32_t>;  // host_id, pid
  struct Live {
    std::int64_t claimed_ns = 0;
    std::string host;
  };
  [[nodiscard]] bool older_than_self(const Key& key, const Live& claim) const;
  void take();
  /// The holder's claim names this one as refused: it has been counted.
  [[nodiscard]] bool holder_counted_self() const;
  void withdraw();

  std::uint32_t rig_id_;
  std::int64_t settle_ns_;
  Claimant self_;
  std::int64_t claimed_ns_;
  Topic topic_;
  PartitionGroup publisher_, subscriber_;
  Writer<mhd_dds_RigClaim> writer_;
  Entity reader_;
  mhd_dds_RigClaim sample_{};
  std::map<Key, Live> live_;  // the other claimants of this rig, alive
  std::set<Key> counted_;     // the younger ones, refused
  std::set<Key> counted_by_;  // the claimants that named this one as refused
  bool refused_self_ = false;
  bool withdrawn_ = false;
  Key holder_key_;
  std::optional<Live> holder_;
  std::string holder_name_;
  std::uint64_t refused_ = 0;
};

}  // namespace mhd::dds
