// intersense: an InterSense tracker (the IS-900 of the thesis's rig, and the SDK's other
// Precision Series models) through the InterSense SDK, loaded from libisense.so when the
// plugin opens. Every station that is on becomes a sensor: station n is sensor n - 1, its
// pose in the tracker frame T (the IS-900's, z down; the rig places it), metres and a unit
// quaternion. A sample is taken when the station says it is new, tracked, finite, in range,
// a unit quaternion, and later by the tracker's own clock than the last one (a frozen
// tracker repeats its last record as new); what fails is dropped and counted, so stale
// tracking fades force and stops the base as it does for every tracker. A link that fails
// every read for `link_timeout_s` ends the run.
#include "isd_runtime.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd_intersense {
namespace {

/// |q| may differ from 1 by this much (the SDK's floats carry 7 digits).
constexpr double kQuaternionNormTolerance = 1e-3;

std::string number(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%g", value);
  return text.data();
}

enum Counter : std::size_t {
  kAccepted, kReadFailures, kNotTracking, kNonFinite, kOutOfRange, kBadQuaternion, kFrozenTime, kCounterCount
};
constexpr std::array<const char*, kCounterCount> kCounterNames{
    "accepted",       "read_failures",         "dropped_not_tracking", "dropped_non_finite",
    "dropped_out_of_range", "dropped_bad_quaternion", "dropped_frozen_time"};

}  // namespace

/// The open tracker: closed when it goes, before the library is unloaded.
class OpenTracker {
 public:
  OpenTracker(const IsdCalls& isd, int port) : isd_(isd), handle_(isd.ISD_OpenTracker(nullptr, static_cast<isd::Dword>(port), 0, 0)) {
    if (handle_ < 1) {
      throw std::runtime_error("ISD_OpenTracker found no InterSense tracker on " +
                               (port == 0 ? std::string("any port") : "port " + std::to_string(port)) +
                               ": is it powered, its cable in, and its port named in isports.ini? (docs/hardware.md)");
    }
  }
  ~OpenTracker() { isd_.ISD_CloseTracker(handle_); }
  OpenTracker(const OpenTracker&) = delete;
  OpenTracker& operator=(const OpenTracker&) = delete;
  [[nodiscard]] isd::Handle handle() const { return handle_; }

 private:
  const IsdCalls& isd_;
  isd::Handle handle_;
};

/// A station that is on: its number and the tracker time of its last sample taken.
struct Station {
  std::uint16_t id;
  double last_time_s = -1.0;
  std::uint64_t sequence = 0;
};

class InterSense {
 public:
  static constexpr std::array kParams{
      mhd::sdk::text("library", "libisense.so", "the InterSense SDK's library to load (a name the loader finds, or a path)"),
      mhd::sdk::integer("port", "", "0", "the tracker's port as the SDK numbers them; 0 searches every port",
                        mhd::sdk::between(0, 64)),
      mhd::sdk::number("max_position_m", "m", "20", "positions farther out, per coordinate, are refused",
                       mhd::sdk::above_up_to(0, 1000)),
      mhd::sdk::number("link_timeout_s", "s", "0.5",
                       "the run ends with a fault once every ISD_GetTrackingData has failed for this long",
                       mhd::sdk::between(0.05, 10)),
  };

  InterSense(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host), runtime_(load_isense(params.text("library"))), isd_(runtime_->calls()),
        tracker_(isd_, static_cast<int>(params.integer("port"))), max_position_m_(params.number("max_position_m")),
        link_timeout_s_(params.number("link_timeout_s")) {
    check_library();
    configure_stations();
  }

  /// The newest record of every station that is on: the samples that pass go to `out`.
  mhd_status tracker_read(std::span<mhd_tracker_sample> out, std::size_t& count) {
    const double now_s = mhd::sdk::host_now(host_);
    if (isd_.ISD_GetTrackingData(tracker_.handle(), &data_.value) == 0) return read_failed(now_s);
    first_failure_s_ = -1.0;
    for (Station& station : stations_) {
      if (count < out.size() && take(station, now_s, out[count])) ++count;
    }
    return count > 0 ? MHD_OK : MHD_NO_DATA;
  }

  std::size_t counters(std::span<mhd_counter> out) const {
    for (std::size_t i = 0; i < kCounterCount && i < out.size(); ++i) out[i] = {kCounterNames[i], counts_[i]};
    return kCounterCount;
  }

 private:
  /// Refuses a library whose structs isd_types.h does not declare.
  void check_library() {
    if (isd_.ISD_GetCommInfo(tracker_.handle(), &info_.value) == 0) {
      throw std::runtime_error("ISD_GetCommInfo failed: the tracker does not answer (is its cable in?)");
    }
    const float version = info_.value.LibVersion;
    if (!(version >= kMinLibVersion && version < kMaxLibVersion)) {
      throw std::runtime_error("the InterSense library is version " + number(version) +
                               ": this plugin knows the data layout of SDK 4.x only (docs/hardware.md)");
    }
  }

  /// Every station that is on reports quaternions and time stamps.
  void configure_stations() {
    for (std::uint16_t id = 1; id <= isd::kMaxStations; ++id) {
      isd::Padded<isd::StationInfo> station;
      if (isd_.ISD_GetStationConfig(tracker_.handle(), &station.value, id, 0) == 0 || station.value.State == 0) continue;
      station.value.AngleFormat = isd::kQuaternion;
      station.value.TimeStamped = 1;
      if (isd_.ISD_SetStationConfig(tracker_.handle(), &station.value, id, 0) == 0) {
        throw std::runtime_error("ISD_SetStationConfig refused quaternions with time stamps for station " +
                                 std::to_string(id) + " of the " + model_name(info_.value.TrackerModel));
      }
      stations_.push_back(Station{.id = id});
    }
    if (stations_.empty()) {
      throw std::runtime_error("no station of the " + model_name(info_.value.TrackerModel) +
                               " is on: turn the base's and the head's stations on (ISDemo)");
    }
  }

  mhd_status read_failed(double now_s) {
    ++counts_[kReadFailures];
    if (first_failure_s_ < 0.0) first_failure_s_ = now_s;
    if (now_s - first_failure_s_ >= link_timeout_s_) {
      throw std::runtime_error("ISD_GetTrackingData has failed for " + number(now_s - first_failure_s_) +
                               " s (link_timeout_s): the link to the " + model_name(info_.value.TrackerModel) +
                               " is lost; check its cable and power");
    }
    return MHD_NO_DATA;
  }

  /// Station `station`'s record as a sample in `out`, when it is new and passes.
  bool take(Station& station, double now_s, mhd_tracker_sample& out) {
    const isd::StationData& d = data_.value.Station[station.id - 1];
    if (d.NewData == 0) return false;
    const std::array<double, 3> p{d.Position[0], d.Position[1], d.Position[2]};
    const std::array<double, 4> q{d.Quaternion[0], d.Quaternion[1], d.Quaternion[2], d.Quaternion[3]};
    const double t_s = d.TimeStamp;
    const Counter verdict = judge(p, q, t_s, d.TrackingStatus, station.last_time_s);
    ++counts_[verdict];
    if (verdict != kAccepted) return false;
    station.last_time_s = t_s;
    out = mhd_tracker_sample{.sensor_id = static_cast<std::uint32_t>(station.id - 1U),
                             .sequence = ++station.sequence,
                             .timestamp_s = now_s,
                             .p_T_m = {p[0], p[1], p[2]},
                             .q_T_wxyz = {q[0], q[1], q[2], q[3]}};
    return true;
  }

  [[nodiscard]] Counter judge(const std::array<double, 3>& p, const std::array<double, 4>& q, double t_s,
                              std::uint8_t tracking_status, double last_time_s) const {
    if (tracking_status == 0) return kNotTracking;
    bool finite = std::isfinite(t_s);
    for (const double v : p) finite = finite && std::isfinite(v);
    for (const double v : q) finite = finite && std::isfinite(v);
    if (!finite) return kNonFinite;
    for (const double v : p) {
      if (std::abs(v) > max_position_m_) return kOutOfRange;
    }
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (std::abs(norm - 1.0) > kQuaternionNormTolerance) return kBadQuaternion;
    if (t_s <= last_time_s) return kFrozenTime;
    return kAccepted;
  }

  mhd_host host_;
  std::unique_ptr<IsdRuntime> runtime_;
  const IsdCalls& isd_;
  OpenTracker tracker_;
  double max_position_m_;
  double link_timeout_s_;
  isd::Padded<isd::TrackerInfo> info_;
  isd::Padded<isd::TrackingData> data_;
  std::vector<Station> stations_;
  std::array<std::uint64_t, kCounterCount> counts_{};
  double first_failure_s_ = -1.0;
};

}  // namespace mhd_intersense

MHD_PLUGIN_ENTRY(mhd_intersense::InterSense,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "InterSense IS-900 and other Precision Series trackers through the InterSense SDK "
                                 "(libisense)"})
