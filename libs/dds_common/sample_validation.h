#pragma once
// What a DDS subscriber checks before a tracker sample reaches the engine. A sample
// that fails is dropped and counted by its first failing reason, in this order:
// unknown rig, non-finite, out of range, bad quaternion, stale, future, sequence
// going backwards. Nothing here allocates after construction.

#include "mhd_dds_types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mhd::dds {

enum class DropReason : std::uint8_t {
  UnknownRig,         ///< another rig's sample (a domain carries several rigs)
  NonFinite,          ///< NaN or infinity in a position, quaternion
  OutOfRange,         ///< a position coordinate beyond max_abs_position_m, or a sensor id >= max_sensors
  BadQuaternion,      ///< norm off 1 by more than quaternion_tolerance
  Stale,              ///< measured more than max_age_s ago
  Future,             ///< measured more than max_future_s ahead of this host's clock
  SequenceBackwards,  ///< not newer than the last accepted sample of its sensor
};
inline constexpr std::size_t kDropReasonCount = 7;

/// "unknown_rig", "non_finite", "out_of_range", "bad_quaternion", "stale", "future",
/// "sequence_backwards".
[[nodiscard]] std::string_view to_string(DropReason reason);

struct TrackerValidationLimits {
  std::uint32_t rig_id = 0;            ///< the only rig accepted
  double max_abs_position_m = 20.0;    ///< per coordinate, in the tracker frame
  std::uint32_t max_sensors = 32;      ///< sensor ids 0 .. max_sensors - 1 (bounds the state kept)
  double quaternion_tolerance = 1e-3;  ///< | |q| - 1 |
  double max_age_s = 0.1;              ///< older samples are stale
  double max_future_s = 0.01;          ///< clock skew allowed
  /// A sensor whose last accepted sample is older than this may start its sequence
  /// over (the tracker server restarted); a backwards step within it is a reorder.
  double restart_after_s = 0.25;
};

struct DropCounts {
  std::uint64_t accepted = 0;
  std::array<std::uint64_t, kDropReasonCount> dropped{};
  [[nodiscard]] std::uint64_t dropped_total() const;
  [[nodiscard]] std::uint64_t operator[](DropReason r) const { return dropped[static_cast<std::size_t>(r)]; }
  /// "accepted 12, dropped 3 (non_finite 1, stale 2)"; reasons with no drop left out.
  [[nodiscard]] std::string summary() const;
};

class TrackerSampleValidator {
 public:
  explicit TrackerSampleValidator(const TrackerValidationLimits& limits);

  /// Checks `sample` against the limits at receive time `now_ns` (CLOCK_REALTIME);
  /// nullopt: accepted (and remembered as its sensor's latest). Counts either way.
  std::optional<DropReason> check(const mhd_dds_TrackerSample& sample, std::int64_t now_ns);
  /// Whether an accepted sample is older than max_age_s at `now_ns`, when it is handed
  /// out; if so it is counted as stale instead of accepted.
  bool expired(const mhd_dds_TrackerSample& sample, std::int64_t now_ns);

  [[nodiscard]] const DropCounts& counts() const { return counts_; }
  [[nodiscard]] const TrackerValidationLimits& limits() const { return limits_; }

 private:
  struct SensorState {
    std::uint32_t sensor_id;
    std::uint64_t last_sequence;
    std::int64_t last_accepted_ns;  ///< receive time
  };
  std::optional<DropReason> reason(const mhd_dds_TrackerSample& sample, std::int64_t now_ns) const;
  std::optional<DropReason> age_reason(std::int64_t timestamp_ns, std::int64_t now_ns) const;
  TrackerValidationLimits limits_;
  std::vector<SensorState> sensors_;
  DropCounts counts_;
};

}  // namespace mhd::dds
