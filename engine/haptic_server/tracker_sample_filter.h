#pragma once
// Which tracker samples the server takes (docs/haptic_server.md, "Status line"): the io
// thread's checks on every sample a tracker plugin returns, as one verdict per sample.

#include "haptic_server/floor_tracker.h"
#include "plugin_host/hardware_io.h"

#include <array>
#include <cstddef>
#include <optional>
#include <cstdint>

namespace mhd {

/// What becomes of one tracker sample.
enum class TrackerSampleVerdict {
  Accepted,
  SequenceBackwards,   ///< dropped: not newer than the sensor's last accepted sample
  FromTheFuture,       ///< dropped: measured after it was read (beyond the clock slack)
  UnknownSensor,       ///< dropped: neither the base's sensor, the head's nor another rig's
  ImplausiblePosition, ///< a fault: not finite, or beyond the tracking range (physical_range.h)
};

/// "accepted", "sequence backwards", "from the future", "unknown sensor", "implausible position".
[[nodiscard]] const char* to_string(TrackerSampleVerdict verdict) noexcept;

struct TrackerSampleFilterSettings {
  std::uint32_t base_sensor_id = 0;
  std::uint32_t head_sensor_id = 1;
  OtherRigSensorList other_rigs;  ///< the other rigs' users' and bases' sensors
  double tracking_range_m = 50.0;
  /// A sample may be this much newer than the host clock at its read (the clocks agree).
  double future_slack_s = 0.01;
  /// A sensor silent this long may start its sequence again (a restarted tracker server).
  double sequence_restart_after_s = 0.25;
};

/// The per-sensor memory behind the checks: the last accepted sequence number and when,
/// for the base's and the head's sensors only. One instance per tracker, driven by one
/// thread; it never allocates, whatever sensors a tracker names.
class TrackerSampleFilter {
 public:
  explicit TrackerSampleFilter(TrackerSampleFilterSettings settings) : settings_(settings) {}

  /// The verdict on `sample`, read from the plugin at host time `read_at_s`. Drops are
  /// checked before the position, so a dropped sample is never a fault. Only an accepted
  /// sample moves its sensor's sequence on; the first sample of the base's or the head's
  /// sensor, whatever its verdict, starts that sensor's memory.
  [[nodiscard]] TrackerSampleVerdict check(const TrackerSample& sample, double read_at_s);

  [[nodiscard]] const TrackerSampleFilterSettings& settings() const noexcept { return settings_; }

 private:
  struct SensorTrack {
    bool seen = false;
    std::uint64_t sequence = 0;
    double accepted_at_s = 0.0;  ///< host time of the last accepted sample
  };
  TrackerSampleFilterSettings settings_;
  /// The slot of a sensor the server takes: 0 the base's, 1 the head's, then each other
  /// rig's head and base.
  [[nodiscard]] std::optional<std::size_t> slot_of(std::uint32_t sensor_id) const noexcept;
  std::array<SensorTrack, 2 + 2 * kMaxOtherRigs> sensors_{};
};

}  // namespace mhd
