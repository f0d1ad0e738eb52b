#pragma once
// The viewer's network state source (the seed's separate visual server): the rig state
// of one rig, read over Cyclone DDS from the `mhd_rig_state` topic that the haptic
// server's `dds_state` display plugin publishes (docs/networking.md).
//
// latest() never blocks: it takes what DDS has already received (dds_take), keeps the
// newest valid state of its rig and returns it; when nothing new came it returns the
// last one again. When no state has come for `stale_after_s` it reports so once
// ("no rig state from rig 1 for 1.0 s ..."), and once more when states come back.
// This header includes no DDS header.

#include "viewer/state_source.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace mhd::viewer {

struct DdsStateSourceOptions {
  std::uint32_t rig_id = 0;
  /// DDS domain; nullopt: the configuration's ($CYCLONEDDS_URI or Cyclone's default).
  std::optional<std::uint32_t> domain_id;
  /// Silence after which the publisher is reported gone (and before the first state).
  double stale_after_s = 1.0;
};

/// What the source has seen so far.
struct DdsStateSourceStatus {
  std::uint64_t received = 0;        ///< valid states of this rig taken
  std::uint64_t dropped_invalid = 0; ///< states of this rig that cannot be drawn (NaN, zero quaternion)
  std::uint64_t other_rigs = 0;      ///< states of other rigs, ignored
  bool has_state = false;
  bool stale = false;                ///< nothing for stale_after_s (reported)
  std::string last_error;            ///< why the last dropped state was dropped
};

class DdsStateSource final : public StateSource {
 public:
  /// Receives each status line ("no rig state from rig 1 for 1.0 s; keeping the last
  /// state", "rig state from rig 1 again after 2.4 s"); default: printed to stderr as
  /// "mhd viewer: <line>".
  using MessageSink = std::function<void(const std::string&)>;

  /// Joins the domain and creates the reader. Throws std::runtime_error with DDS's reason
  /// ("dds_create_participant: Error") when it cannot.
  explicit DdsStateSource(const DdsStateSourceOptions& options, MessageSink sink = {});
  ~DdsStateSource() override;
  DdsStateSource(const DdsStateSource&) = delete;
  DdsStateSource& operator=(const DdsStateSource&) = delete;

  /// poll() at the steady clock's now.
  [[nodiscard]] std::optional<RigState> latest() override;
  /// Takes what has arrived (never waits), updates the status as of `now_s` (any
  /// monotonic clock in seconds, the same for every call) and returns the newest state.
  [[nodiscard]] std::optional<RigState> poll(double now_s);

  [[nodiscard]] const DdsStateSourceStatus& status() const noexcept;
  /// Matched publishers seen so far (discovery is asynchronous).
  [[nodiscard]] std::uint32_t matched_publishers() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Seconds on the steady clock (what latest() passes to poll()).
[[nodiscard]] double steady_now_s() noexcept;

}  // namespace mhd::viewer
