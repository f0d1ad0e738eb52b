#include "dds_common/sample_validation.h"

#include <cmath>

namespace mhd::dds {
namespace {

constexpr double kNsPerS = 1e9;

// RigStatus carries one count per reason.
static_assert(sizeof(mhd_dds_RigStatus::tracker_dropped) / sizeof(std::uint64_t) == kDropReasonCount);

bool finite_all(const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

}  // namespace

std::string_view to_string(DropReason reason) {
  switch (reason) {
    case DropReason::UnknownRig: return "unknown_rig";
    case DropReason::NonFinite: return "non_finite";
    case DropReason::OutOfRange: return "out_of_range";
    case DropReason::BadQuaternion: return "bad_quaternion";
    case DropReason::Stale: return "stale";
    case DropReason::Future: return "future";
    case DropReason::SequenceBackwards: return "sequence_backwards";
  }
  return "?";
}

std::uint64_t DropCounts::dropped_total() const {
  std::uint64_t total = 0;
  for (const std::uint64_t n : dropped) total += n;
  return total;
}

std::string DropCounts::summary() const {
  std::string s = "accepted " + std::to_string(accepted) + ", dropped " + std::to_string(dropped_total());
  std::string detail;
  for (std::size_t i = 0; i < kDropReasonCount; ++i) {
    if (dropped[i] == 0) continue;
    if (!detail.empty()) detail += ", ";
    detail += std::string(to_string(static_cast<DropReason>(i))) + " " + std::to_string(dropped[i]);
  }
  if (!detail.empty()) s += " (" + detail + ")";
  return s;
}

TrackerSampleValidator::TrackerSampleValidator(const TrackerValidationLimits& limits) : limits_(limits) {
  sensors_.reserve(limits.max_sensors);
}

std::optional<DropReason> TrackerSampleValidator::reason(const mhd_dds_TrackerSample& s, std::int64_t now_ns) const {
  if (s.rig_id != limits_.rig_id) return DropReason::UnknownRig;
  if (!finite_all(s.p_T_m, 3) || !finite_all(s.q_T_wxyz, 4)) return DropReason::NonFinite;
  if (s.sensor_id >= limits_.max_sensors) return DropReason::OutOfRange;
  for (const double p : s.p_T_m) {
    if (std::abs(p) > limits_.max_abs_position_m) return DropReason::OutOfRange;
  }
  const double norm = std::sqrt(s.q_T_wxyz[0] * s.q_T_wxyz[0] + s.q_T_wxyz[1] * s.q_T_wxyz[1] +
                                s.q_T_wxyz[2] * s.q_T_wxyz[2] + s.q_T_wxyz[3] * s.q_T_wxyz[3]);
  if (!(std::abs(norm - 1.0) <= limits_.quaternion_tolerance)) return DropReason::BadQuaternion;
  if (const std::optional<DropReason> r = age_reason(s.timestamp_ns, now_ns)) return r;
  for (const SensorState& sensor : sensors_) {
    if (sensor.sensor_id != s.sensor_id) continue;
    const double since_last_s = static_cast<double>(now_ns - sensor.last_accepted_ns) / kNsPerS;
    if (s.sequence_number <= sensor.last_sequence && since_last_s <= limits_.restart_after_s) {
      return DropReason::SequenceBackwards;
    }
  }
  return std::nullopt;
}

std::optional<DropReason> TrackerSampleValidator::age_reason(std::int64_t timestamp_ns, std::int64_t now_ns) const {
  // now_ns - timestamp_ns would overflow for a timestamp more than ~292 years from now
  // (the peer sends any 64-bit value): such a sample is stale or from the future.
  std::int64_t age_ns = 0;
  if (__builtin_sub_overflow(now_ns, timestamp_ns, &age_ns)) {
    return timestamp_ns < 0 ? DropReason::Stale : DropReason::Future;
  }
  const double age_s = static_cast<double>(age_ns) / kNsPerS;
  if (age_s > limits_.max_age_s) return DropReason::Stale;
  if (-age_s > limits_.max_future_s) return DropReason::Future;
  return std::nullopt;
}

bool TrackerSampleValidator::expired(const mhd_dds_TrackerSample& s, std::int64_t now_ns) {
  if (age_reason(s.timestamp_ns, now_ns) != DropReason::Stale) return false;
  --counts_.accepted;
  ++counts_.dropped[static_cast<std::size_t>(DropReason::Stale)];
  return true;
}

std::optional<DropReason> TrackerSampleValidator::check(const mhd_dds_TrackerSample& s, std::int64_t now_ns) {
  const std::optional<DropReason> r = reason(s, now_ns);
  if (r) {
    ++counts_.dropped[static_cast<std::size_t>(*r)];
    return r;
  }
  ++counts_.accepted;
  for (SensorState& sensor : sensors_) {
    if (sensor.sensor_id == s.sensor_id) {
      sensor.last_sequence = s.sequence_number;
      sensor.last_accepted_ns = now_ns;
      return std::nullopt;
    }
  }
  sensors_.push_back({s.sensor_id, s.sequence_number, now_ns});
  return std::nullopt;
}

}  // namespace mhd::dds
