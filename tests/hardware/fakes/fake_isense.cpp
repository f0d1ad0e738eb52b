// A fake of the InterSense SDK's libisense for the intersense plugin's tests, loaded through
// the real dlopen path in its place (fake_hardware.h: its configuration and log). It
// implements the documented calls the plugin makes, with the SDK 4.x layout of
// plugins/tracker/intersense/isd_types.h, in front of a simulated IS-900 on the POMHI rig's
// ceiling (scenes/rigs/pomhi.xml): station 1 on the base, at its nominal pose (the base at
// the world origin, heading 0); station 2 on the user's head, 1.65 m up and 0.9 m in front of
// the world origin; stations 3 to 8 off. A station reports quaternions and time stamps only
// when it was configured to, as the SDK does, and a new record every 1/180 s.
// Its log's events:
//   open          ISD_OpenTracker (a: the port asked)
//   configure     ISD_SetStationConfig (a: station, b: angle format, c: time stamped)
//   record        a new record of station 1 (a: its time stamp, b and c: its y and z)
//   read_failed   ISD_GetTrackingData failed
//   close         ISD_CloseTracker
#include "fake_hardware.h"
#include "tracker/intersense/isd_types.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <thread>

namespace isd = mhd_intersense::isd;
using mhd::fake::Fault;

namespace {

constexpr isd::Handle kHandle = 1;
constexpr double kRecordPeriodS = 1.0 / 180.0;
constexpr double kDropoutS = 1.0;

struct Pose {
  std::array<float, 3> p_T_m;
  std::array<float, 4> q_T_wxyz;
};
// Rotated 180 degrees about the tracker's y, as pomhi.xml's base_sensor frame.
constexpr Pose kBaseStation{{0.206F, 0.0F, 1.4432F}, {0.0F, 0.0F, 1.0F, 0.0F}};
constexpr Pose kHeadStation{{-0.9F, 0.0F, 0.974F}, {1.0F, 0.0F, 0.0F, 0.0F}};

struct Tracker : mhd::fake::FakeBase {
  std::mutex mutex;
  bool open = false;
  double opened_at_s = 0.0;
  double last_record_s = 0.0;
  float record_time_s = 0.0F;
  std::array<isd::StationInfo, isd::kMaxStations> stations{};

  Tracker() {
    for (std::uint32_t i = 0; i < stations.size(); ++i) {
      stations[i].ID = i + 1;
      stations[i].State = i < 2 ? 1 : 0;
      stations[i].AngleFormat = 1;  // Euler, the SDK's default
    }
  }

  void fill(isd::StationData& d, const isd::StationInfo& station, const Pose& pose, bool new_record) const {
    d = isd::StationData{};
    d.TrackingStatus = 200;
    d.NewData = new_record ? 1 : 0;
    for (std::size_t i = 0; i < 3; ++i) d.Position[i] = pose.p_T_m[i];
    if (station.AngleFormat == isd::kQuaternion) {
      for (std::size_t i = 0; i < 4; ++i) d.Quaternion[i] = pose.q_T_wxyz[i];
    }
    if (station.TimeStamped != 0) d.TimeStamp = record_time_s;
    if (config.fault == Fault::NanPosition && struck()) d.Position[1] = std::numeric_limits<float>::quiet_NaN();
    if (config.fault == Fault::Dropout && struck() && !fault_clock.struck(config.fault_after_s + kDropoutS)) {
      d.TrackingStatus = 0;  // the station lost: no ultrasound reached it
    }
  }
};

Tracker& tracker() {
  static Tracker t;
  return t;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) isd::Handle ISD_OpenTracker(void* /*parent*/, isd::Dword port,
                                                                   isd::Bool /*info*/, isd::Bool /*verbose*/) {
  Tracker& t = tracker();
  const std::lock_guard lock(t.mutex);
  if (t.config.fault == Fault::Unplugged) return -1;
  t.open = true;
  t.opened_at_s = mhd::fake::now_s();
  t.log.add("open", port);
  return kHandle;
}

__attribute__((visibility("default"))) isd::Bool ISD_CloseTracker(isd::Handle handle) {
  Tracker& t = tracker();
  const std::lock_guard lock(t.mutex);
  if (handle != kHandle || !t.open) return 0;
  t.open = false;
  t.log.add("close");
  return 1;
}

__attribute__((visibility("default"))) isd::Bool ISD_GetCommInfo(isd::Handle handle, isd::TrackerInfo* info) {
  Tracker& t = tracker();
  const std::lock_guard lock(t.mutex);
  if (handle != kHandle || !t.open || t.config.fault == Fault::ErrorEveryCall) return 0;
  *info = isd::TrackerInfo{};
  info->LibVersion = t.config.fault == Fault::OldLibrary ? 3.58F : 4.2381F;
  info->TrackerType = 1;  // ISD_PRECISION_SERIES
  info->TrackerModel = isd::kModelIs900;
  info->RecordsPerSec = 180;
  return 1;
}

__attribute__((visibility("default"))) isd::Bool ISD_GetStationConfig(isd::Handle handle, isd::StationInfo* station,
                                                                      std::uint16_t id, isd::Bool /*verbose*/) {
  Tracker& t = tracker();
  const std::lock_guard lock(t.mutex);
  if (handle != kHandle || !t.open || id < 1 || id > isd::kMaxStations) return 0;
  *station = t.stations[id - 1U];
  return 1;
}

__attribute__((visibility("default"))) isd::Bool ISD_SetStationConfig(isd::Handle handle, isd::StationInfo* station,
                                                                      std::uint16_t id, isd::Bool /*verbose*/) {
  Tracker& t = tracker();
  const std::lock_guard lock(t.mutex);
  if (handle != kHandle || !t.open || id < 1 || id > isd::kMaxStations) return 0;
  t.stations[id - 1U] = *station;
  t.log.add("configure", id, station->AngleFormat, station->TimeStamped);
  return 1;
}

__attribute__((visibility("default"))) isd::Bool ISD_GetTrackingData(isd::Handle handle, isd::TrackingData* data) {
  Tracker& t = tracker();
  std::unique_lock lock(t.mutex);
  if (handle != kHandle || !t.open) return 0;
  t.fault_clock.force_enabled();  // a tracker's faults count from its first read
  if (t.config.fault == Fault::Hang && t.struck()) {
    lock.unlock();
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // a serial read that never returns
  }
  if (t.config.fault == Fault::CommError && t.struck()) {
    t.log.add("read_failed");
    return 0;
  }
  const double now = mhd::fake::now_s();
  const bool new_record = now - t.last_record_s >= kRecordPeriodS;
  if (new_record) {
    t.last_record_s = now;
    // A frozen tracker repeats its last record, time stamp and all, as new.
    if (!(t.config.fault == Fault::FrozenTimestamp && t.struck())) t.record_time_s = static_cast<float>(now - t.opened_at_s);
  }
  std::memset(data, 0, sizeof(*data));
  t.fill(data->Station[0], t.stations[0], kBaseStation, new_record);
  t.fill(data->Station[1], t.stations[1], kHeadStation, new_record);
  if (new_record) t.log.add("record", t.record_time_s, data->Station[0].Position[1], data->Station[0].Position[2]);
  return 1;
}

}  // extern "C"
