#pragma once
// The haptic server's settings, from the scene: <haptics> (rate, force limit) and the
// <server> block. <server> params (all optional):
//   tracker_timeout_s (0.05)  force is zero and the base stops when the newest base pose
//                             is this old; tracker_fade_s (0.02) the force fade before it
//   hip_jump_m (0.01)         a HIP step per tick above this fades force (force_safety.h)
//   fade_in_s (0.5)           force returns over this long after a fault
//   predict_base_pose (true)  BasePosePredictor between tracker samples, else hold
//   base_sensor_id (0), head_sensor_id (1)   tracker sensors on the robot and the head
//   base_pose_source (tracker)  where the base pose comes from: the tracker's base sensor,
//                             or `odometry`, the base plugin's own state (base_read, e.g. a
//                             ROS 2 base's Odometry), whose frame is then the world's
//   io_rate_hz (1000), base_rate_hz (10), display_rate_hz (60)
//   base_max_speed_mps (0.5), base_max_omega_degps (40), keep_out_m (the planner's
//                             robot + human radius, else 0.475): the base guard
//   record_flush_s (0.05)     the recording reaches the disk at least this often
//   tick_on_tracker_sample (true)   with a tracker that can wake the host (tracker_wait),
//                             a new base-sensor sample starts an extra haptic tick at
//                             once, between the 1 ms deadlines; min_tick_interval_s
//                             (0.0002) is the least time between any two ticks
//   plugin_call_timeout_s (0.1)  a device, tracker or base call that has not returned
//                             after this long ends the run (the others reach their
//                             safe state; a stuck device must rely on its own watchdog)
//   tracking_range_m (50)     a tracked sensor farther than this from the tracker's origin
//                             is a fault (physical_range.h)
//   other_rig_sensors ("")    the other rigs on the floor, as HEAD:BASE pairs of this
//                             tracker's sensor ids ("2:3 4:5"): their users and bases are
//                             the planner's keep-outs (planner/floor_view.h)
//   other_rigs_timeout_s (0.3)  an other rig's sensor unseen this long, or never seen,
//                             holds the base (the planner's `held`)
// Every number's range is declared in kServerNumbers: `mhd validate` and `mhd run` judge
// <server> by server_settings_from alone.

#include "haptic_server/floor_tracker.h"
#include "haptic_server/haptic_tick.h"
#include "safety/base_command_guard.h"
#include "diagnostics/result.h"
#include "planner/planner_settings.h"
#include "scene/scene_description.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace mhd {

/// A numeric <server> parameter and the range it must lie in (inclusive).
struct ServerNumber {
  std::string_view name;
  double low;
  double high;
  std::string_view unit;
};

/// Every numeric <server> parameter. The bounds are what a host loop and the hardware can
/// live with: a tiny rate is a near-infinite period, a huge timeout no watchdog at all.
inline constexpr std::array<ServerNumber, 15> kServerNumbers{{
    {"tracker_timeout_s", 0.001, 10.0, "s"},
    {"tracker_fade_s", 0.0, 10.0, "s"},
    {"hip_jump_m", 1e-5, 1.0, "m"},
    {"fade_in_s", 0.0, 60.0, "s"},
    {"io_rate_hz", 10.0, 20'000.0, "Hz"},
    {"base_rate_hz", 1.0, 1000.0, "Hz"},
    {"display_rate_hz", 1.0, 1000.0, "Hz"},
    {"base_max_speed_mps", 0.001, 10.0, "m/s"},
    {"base_max_omega_degps", 0.01, 3600.0, "deg/s"},
    {"keep_out_m", 0.0, 100.0, "m"},
    {"record_flush_s", 0.001, 60.0, "s"},
    {"min_tick_interval_s", 0.0, 0.01, "s"},
    {"plugin_call_timeout_s", 0.001, 60.0, "s"},
    {"tracking_range_m", 1.0, 1000.0, "m"},
    {"other_rigs_timeout_s", 0.001, 10.0, "s"},
}};

/// The sensor ids (<server> base_sensor_id, head_sensor_id) are integers in [0, this].
inline constexpr std::uint64_t kMaxSensorId = 0xFFFF'FFFFu;

/// Where the base pose estimate comes from (<server> base_pose_source).
enum class BasePoseSource { Tracker, Odometry };

struct ServerSettings {
  HapticTickSettings tick;
  double haptic_rate_hz = 1000.0;
  double io_rate_hz = 1000.0;
  double base_rate_hz = 10.0;
  double display_rate_hz = 60.0;
  std::uint32_t base_sensor_id = 0;
  std::uint32_t head_sensor_id = 1;
  BasePoseSource base_pose_source = BasePoseSource::Tracker;
  BaseCommandGuardSettings base_guard;
  double record_flush_s = 0.05;
  bool tick_on_tracker_sample = true;
  double min_tick_interval_s = 0.0002;
  double plugin_call_timeout_s = 0.1;
  double tracking_range_m = 50.0;
  OtherRigSensorList other_rigs;
  double other_rigs_timeout_s = 0.3;
  /// Where the scene's planner keeps the HIP (base frame): the device's reported
  /// workspace, moved in by the rig's usable margin. Empty with no planner of the scene's.
  std::optional<PlanarBox> planner_usable_B;
};

/// The <server> parameters, or every one that is wrong (each at its file:line).
[[nodiscard]] Result<ServerSettings> server_settings_from(const SceneDescription& scene);

}  // namespace mhd
