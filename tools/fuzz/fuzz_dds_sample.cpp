// libFuzzer target: DDS tracker-sample validation (libs/dds_common/sample_validation.h)
// and the conversion of accepted samples to the plugin ABI (dds_convert.h).
//
// The input drives one validator: first its limits (sane ranges, as the dds tracker
// plugin's parameter reader allows), then a stream of samples, each received at a
// receive time that mostly moves forward. A sample is either the struct's raw bytes
// (any rig, NaN, infinities, any timestamp) or built near a valid one (right rig, small
// sensor ids, unit-ish quaternion, recent timestamp, sequences stepping around the last),
// with any of its fields then replaced by raw bytes.
//
// Invariants (a violation traps): each verdict equals an independent model of the
// documented rules (first failing reason in the documented order); accepted samples are
// finite, in range, with |q| within tolerance, and convert to a finite ABI sample whose
// host time lies within the age limits; the counts add up (accepted + dropped = checked,
// per reason as modelled) and the summary says so.
#include "dds_common/dds_convert.h"
#include "dds_common/sample_validation.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <string>

namespace {

using mhd::dds::DropReason;
using mhd::dds::TrackerValidationLimits;

constexpr double kNsPerS = 1e9;
__extension__ typedef __int128 Int128;  // exact differences of any two int64 nanoseconds

[[noreturn]] void violated(const std::string& what) {
  std::fprintf(stderr, "\n*** mhd-fuzz-dds-sample: invariant violated: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

std::string reason_text(const std::optional<DropReason>& r) {
  return r ? std::string(mhd::dds::to_string(*r)) : std::string("accepted");
}

/// The documented rules, written independently of the validator; time differences in
/// 128-bit integers so that no timestamp can overflow them.
class Model {
 public:
  explicit Model(const TrackerValidationLimits& limits) : limits_(limits) {}

  std::optional<DropReason> verdict(const mhd_dds_TrackerSample& s, std::int64_t now_ns) const {
    if (s.rig_id != limits_.rig_id) return DropReason::UnknownRig;
    for (const double v : s.p_T_m) {
      if (!std::isfinite(v)) return DropReason::NonFinite;
    }
    for (const double v : s.q_T_wxyz) {
      if (!std::isfinite(v)) return DropReason::NonFinite;
    }
    if (s.sensor_id >= limits_.max_sensors) return DropReason::OutOfRange;
    for (const double v : s.p_T_m) {
      if (std::abs(v) > limits_.max_abs_position_m) return DropReason::OutOfRange;
    }
    double n2 = 0.0;
    for (const double v : s.q_T_wxyz) n2 += v * v;
    if (!(std::abs(std::sqrt(n2) - 1.0) <= limits_.quaternion_tolerance)) return DropReason::BadQuaternion;
    const double age_s = seconds(static_cast<Int128>(now_ns) - s.timestamp_ns);
    if (age_s > limits_.max_age_s) return DropReason::Stale;
    if (-age_s > limits_.max_future_s) return DropReason::Future;
    if (const auto it = last_.find(s.sensor_id); it != last_.end()) {
      const double since_s = seconds(static_cast<Int128>(now_ns) - it->second.accepted_ns);
      if (s.sequence_number <= it->second.sequence && since_s <= limits_.restart_after_s) {
        return DropReason::SequenceBackwards;
      }
    }
    return std::nullopt;
  }

  void record(const mhd_dds_TrackerSample& s, std::int64_t now_ns, const std::optional<DropReason>& r) {
    if (r) {
      ++dropped_[static_cast<std::size_t>(*r)];
      return;
    }
    ++accepted_;
    last_[s.sensor_id] = Last{s.sequence_number, now_ns};
  }

  void check_counts(const mhd::dds::DropCounts& c, std::uint64_t checked) const {
    if (c.accepted != accepted_) violated("accepted count differs from the model");
    for (std::size_t i = 0; i < mhd::dds::kDropReasonCount; ++i) {
      if (c.dropped[i] != dropped_[i]) {
        violated("dropped count for " + reason_text(static_cast<DropReason>(i)) + " differs from the model");
      }
    }
    if (c.accepted + c.dropped_total() != checked) violated("accepted + dropped != samples checked");
    const std::string expect =
        "accepted " + std::to_string(c.accepted) + ", dropped " + std::to_string(c.dropped_total());
    if (c.summary().rfind(expect, 0) != 0) violated("summary '" + c.summary() + "' does not start with '" + expect + "'");
  }

 private:
  // The validator divides a double by 1e9; so does the model, from the exact difference.
  static double seconds(Int128 ns) { return static_cast<double>(ns) / kNsPerS; }

  struct Last {
    std::uint64_t sequence;
    std::int64_t accepted_ns;
  };
  TrackerValidationLimits limits_;
  std::map<std::uint32_t, Last> last_;
  std::uint64_t accepted_ = 0;
  std::array<std::uint64_t, mhd::dds::kDropReasonCount> dropped_{};
};

TrackerValidationLimits consume_limits(FuzzedDataProvider& in) {
  TrackerValidationLimits l;
  if (in.ConsumeBool()) return l;  // the defaults
  l.rig_id = in.ConsumeIntegralInRange<std::uint32_t>(0, 3);
  l.max_abs_position_m = in.ConsumeFloatingPointInRange(1e-3, 1e3);
  l.max_sensors = in.ConsumeIntegralInRange<std::uint32_t>(0, 64);
  l.quaternion_tolerance = in.ConsumeFloatingPointInRange(1e-9, 0.5);
  l.max_age_s = in.ConsumeFloatingPointInRange(1e-4, 10.0);
  l.max_future_s = in.ConsumeFloatingPointInRange(0.0, 1.0);
  l.restart_after_s = in.ConsumeFloatingPointInRange(1e-4, 10.0);
  return l;
}

mhd_dds_TrackerSample consume_raw(FuzzedDataProvider& in) {
  mhd_dds_TrackerSample s{};
  std::array<unsigned char, sizeof s> bytes{};
  const std::size_t n = in.ConsumeData(bytes.data(), bytes.size());
  std::memcpy(&s, bytes.data(), n);  // missing bytes stay zero
  return s;
}

double raw_double(FuzzedDataProvider& in) {
  const auto bits = in.ConsumeIntegral<std::uint64_t>();
  double v = 0.0;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

double consume_small(FuzzedDataProvider& in, double scale) {
  return scale * (static_cast<double>(in.ConsumeIntegral<std::int16_t>()) / 32768.0);
}

mhd_dds_TrackerSample consume_near_valid(FuzzedDataProvider& in, const TrackerValidationLimits& l,
                                         std::int64_t now_ns, std::uint64_t& sequence) {
  mhd_dds_TrackerSample s{};
  s.rig_id = in.ConsumeIntegralInRange<std::uint32_t>(0, 7) == 0 ? l.rig_id + 1 : l.rig_id;
  s.sensor_id = in.ConsumeIntegralInRange<std::uint32_t>(0, 3) == 0 ? in.ConsumeIntegral<std::uint32_t>()
                                                                    : in.ConsumeIntegralInRange<std::uint32_t>(0, 4);
  sequence += static_cast<std::uint64_t>(in.ConsumeIntegralInRange<std::int64_t>(-3, 5));
  s.sequence_number = sequence;
  // Age from 0.5 s in the future to 1 s old, in whole microseconds, sometimes to the ns.
  s.timestamp_ns = now_ns - in.ConsumeIntegralInRange<std::int64_t>(-500000, 1000000) * 1000 -
                   in.ConsumeIntegralInRange<std::int64_t>(0, 999);
  for (double& p : s.p_T_m) p = consume_small(in, 2.0 * l.max_abs_position_m);
  double n2 = 0.0;
  for (double& q : s.q_T_wxyz) {
    q = consume_small(in, 1.0);
    n2 += q * q;
  }
  const double n = std::sqrt(n2);
  const double stretch = 1.0 + consume_small(in, 4.0 * l.quaternion_tolerance);
  for (double& q : s.q_T_wxyz) q = n > 0.0 ? q / n * stretch : 0.0;
  if (n == 0.0) s.q_T_wxyz[0] = stretch;
  // Any field may instead carry raw bytes (a peer can send anything in any one field).
  const auto raw_fields = in.ConsumeIntegral<std::uint8_t>();
  if ((raw_fields & 0x01u) != 0) s.rig_id = in.ConsumeIntegral<std::uint32_t>();
  if ((raw_fields & 0x02u) != 0) s.sensor_id = in.ConsumeIntegral<std::uint32_t>();
  if ((raw_fields & 0x04u) != 0) s.sequence_number = in.ConsumeIntegral<std::uint64_t>();
  if ((raw_fields & 0x08u) != 0) s.timestamp_ns = in.ConsumeIntegral<std::int64_t>();
  if ((raw_fields & 0x10u) != 0) s.p_T_m[in.ConsumeIntegralInRange<std::size_t>(0, 2)] = raw_double(in);
  if ((raw_fields & 0x20u) != 0) s.q_T_wxyz[in.ConsumeIntegralInRange<std::size_t>(0, 3)] = raw_double(in);
  return s;
}

void check_accepted(const mhd_dds_TrackerSample& s, std::int64_t now_ns, const TrackerValidationLimits& l) {
  if (s.rig_id != l.rig_id || s.sensor_id >= l.max_sensors) violated("accepted another rig or sensor id");
  double n2 = 0.0;
  for (const double v : s.q_T_wxyz) {
    if (!std::isfinite(v)) violated("accepted a non-finite quaternion");
    n2 += v * v;
  }
  for (const double v : s.p_T_m) {
    if (!std::isfinite(v) || std::abs(v) > l.max_abs_position_m) violated("accepted a position out of range");
  }
  if (!(std::abs(std::sqrt(n2) - 1.0) <= l.quaternion_tolerance)) violated("accepted a non-unit quaternion");
  // The conversion the subscriber applies to what it accepts.
  constexpr double kHostNow_s = 1000.0;
  const double t_s = mhd::dds::host_from_realtime(s.timestamp_ns, kHostNow_s, now_ns);
  const mhd_tracker_sample abi = mhd::dds::from_dds(s, t_s);
  if (!std::isfinite(abi.timestamp_s) || abi.timestamp_s < kHostNow_s - l.max_age_s - 1e-6 ||
      abi.timestamp_s > kHostNow_s + l.max_future_s + 1e-6) {
    violated("accepted sample's host time " + std::to_string(abi.timestamp_s) + " outside the age limits");
  }
  if (abi.sensor_id != s.sensor_id || abi.sequence != s.sequence_number) violated("conversion changed ids");
  for (std::size_t i = 0; i < 3; ++i) {
    if (abi.p_T_m[i] != s.p_T_m[i]) violated("conversion changed the position");
  }
  for (std::size_t i = 0; i < 4; ++i) {
    if (!std::isfinite(abi.q_T_wxyz[i])) violated("conversion made the quaternion non-finite");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const TrackerValidationLimits limits = consume_limits(in);
  mhd::dds::TrackerSampleValidator validator(limits);
  Model model(limits);
  // A CLOCK_REALTIME reading between 2023 and 2026.
  std::int64_t now_ns = in.ConsumeIntegralInRange<std::int64_t>(1'700'000'000, 1'800'000'000) * 1'000'000'000;
  std::uint64_t sequence = in.ConsumeIntegralInRange<std::uint64_t>(0, 3) == 0 ? in.ConsumeIntegral<std::uint64_t>()
                                                                              : 0;
  std::uint64_t checked = 0;
  while (in.remaining_bytes() > 0 && checked < 4096) {
    // Receive times mostly advance (up to 0.5 s); a realtime clock may also step back.
    now_ns += in.ConsumeIntegralInRange<std::int64_t>(-1'000'000, 500'000'000);
    const mhd_dds_TrackerSample s =
        in.ConsumeBool() ? consume_raw(in) : consume_near_valid(in, limits, now_ns, sequence);
    const std::optional<DropReason> expected = model.verdict(s, now_ns);
    const std::optional<DropReason> got = validator.check(s, now_ns);
    ++checked;
    if (got != expected) violated("verdict " + reason_text(got) + ", the rules say " + reason_text(expected));
    if (!got) check_accepted(s, now_ns, limits);
    model.record(s, now_ns, got);
  }
  model.check_counts(validator.counts(), checked);
  return 0;
}
