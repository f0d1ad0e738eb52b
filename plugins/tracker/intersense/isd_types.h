#pragma once
// The InterSense SDK's types as its 4.x isense.h lays them out for Linux (Bool, DWORD and
// LONG 32 bits), declared here because the SDK is not a Debian package. Only the fields the
// plugin reads or writes are named; the rest are padding of the documented size, checked
// by the static_asserts below.
//
// The layout has changed between SDK versions, and the library fills caller-owned
// structs: every struct the library writes goes to it inside Padded<>, with slack after
// it, so a newer library's longer struct cannot write past the plugin's memory. The
// plugin then refuses a library whose version it does not know (isd_runtime.h).

#include <cstddef>
#include <cstdint>

namespace mhd_intersense::isd {

using Bool = std::int32_t;
using Dword = std::uint32_t;
using Handle = std::int32_t;  ///< ISD_TRACKER_HANDLE: > 0 when open

constexpr int kMaxStations = 8;  ///< ISD_MAX_STATIONS of the full (not ISENSE_LIMITED) SDK
constexpr Dword kQuaternion = 2; ///< ISD_STATION_INFO_TYPE::AngleFormat
constexpr Dword kModelIs900 = 3; ///< ISD_SYSTEM_MODEL's ISD_IS900

/// ISD_TRACKER_INFO_TYPE: what ISD_GetCommInfo fills.
struct TrackerInfo {
  float LibVersion;
  Dword TrackerType;
  Dword TrackerModel;
  Dword Port;
  Dword RecordsPerSec;
  float KBitsPerSec;
  std::byte rest[84 - 24];
};
static_assert(sizeof(TrackerInfo) == 84);

/// ISD_STATION_INFO_TYPE: a station's configuration (ISD_GetStationConfig and
/// ISD_SetStationConfig; the plugin gets it, changes the angle format and time stamps, and
/// sets it back).
struct StationInfo {
  Dword ID;
  Bool State;
  Bool Compass;
  std::int32_t InertiaCube;
  Dword Enhancement;
  Dword Sensitivity;
  Dword Prediction;
  Dword AngleFormat;
  Bool TimeStamped;
  std::byte rest[96 - 36];
};
static_assert(sizeof(StationInfo) == 96);
static_assert(offsetof(StationInfo, AngleFormat) == 28 && offsetof(StationInfo, TimeStamped) == 32);

/// ISD_STATION_DATA_TYPE: one station's newest data. Position in metres and Quaternion
/// (w, x, y, z) in the tracker's frame (the IS-900's: z down); TimeStamp in seconds of the
/// tracker's clock, when TimeStamped is on. TrackingStatus is 0 while the station is lost.
struct StationData {
  std::uint8_t TrackingStatus;
  std::uint8_t NewData;
  std::uint8_t CommIntegrity;
  std::uint8_t BatteryState;
  float Euler[3];
  float Quaternion[4];
  float Position[3];
  float TimeStamp;
  std::byte rest[444 - 48];
};
static_assert(sizeof(StationData) == 444);
static_assert(offsetof(StationData, Quaternion) == 16 && offsetof(StationData, Position) == 32 &&
              offsetof(StationData, TimeStamp) == 44);

/// ISD_TRACKING_DATA_TYPE: every station's, station n at Station[n - 1].
struct TrackingData {
  StationData Station[kMaxStations];
};
static_assert(sizeof(TrackingData) == 3552);

/// T followed by slack the library may write into without harm.
template <class T>
struct Padded {
  T value{};
  std::byte slack[16384]{};
};

}  // namespace mhd_intersense::isd
