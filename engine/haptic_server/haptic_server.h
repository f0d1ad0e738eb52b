#pragma once
// The haptic server (thesis ch. 2.6, 7.1): runs a scene on the plugins it names.
//
// Threads, each driving only its own plugins (an instance is driven by one thread):
//   haptic   1 kHz (the scene's rate), absolute deadlines: device read -> HapticTick
//            (HIP, proxy, safety, torques) -> device write. Never locks, never allocates.
//   io       tracker and base plugins (io_rate_hz): tracker samples
//            to the haptic thread; base commands from the planner, through the
//            BaseCommandGuard (stale base or head data, or a fault, stops the base), to the base.
//   planner  10 Hz: the base motion planner (holds still until one is set).
//   display  60 Hz: the newest state to every display plugin.
//   recorder writes the CSV recording, flushed at least every record_flush_s.
// A desktop rig (<rig kind="desktop">, docs/desktop.md) has a device and displays only:
// no io or planner thread, and the haptic thread renders with the device fixed at X_WD.
// The simulated user is not the server's: the simulated plugins move it in the world
// they share (libs/sim_world); the server only checks the scene's <simulated_user>.
// Hand-offs into and out of the haptic thread are lock-free: SPSC rings for events
// (tracker samples, commands, recording rows) and triple buffers for state. Other
// threads share a few values behind a mutex.
//
// Any plugin error or a plugin asking to be stopped ends the run: the haptic thread
// commands zero torque, the io thread commands a stopped base, every plugin is stopped
// and closed, and the report carries the error naming the plugin and its scene line.

#include "haptic_server/server_settings.h"
#include "haptic_server/server_status.h"
#include "kinematics/base_pose.h"
#include "planner/floor_view.h"
#include "diagnostics/result.h"
#include "scene/scene_description.h"
#include "scene_compiler/compiled_scene.h"

#include <Eigen/Core>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mhd {

/// What the base planner sees each base period.
struct BasePlanInput {
  double t_s = 0.0;
  BasePose base;  ///< predicted, as the haptic loop uses it
  bool hip_valid = false;
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  bool user_known = false;  ///< a head pose has arrived
  Eigen::Vector2d user_xz_W_m = Eigen::Vector2d::Zero();
  double user_heading_rad = 0.0;  ///< the head's line of sight, projected on the floor
  Eigen::Vector2d user_velocity_W_mps = Eigen::Vector2d::Zero();  ///< smoothed, from the head track
  // Each input's age at t_s (+inf: never measured); a plan on anything older than
  // max_input_age_s (the tracker timeout) holds the base still.
  double head_age_s = std::numeric_limits<double>::infinity();
  double base_age_s = std::numeric_limits<double>::infinity();
  double hip_age_s = std::numeric_limits<double>::infinity();
  double max_input_age_s = 0.05;
  /// The other rigs on the floor as this rig's tracker last saw them (none declared: empty),
  /// and how old their data may be before the base holds (planner/floor_view.h).
  FloorView floor;
  double floor_timeout_s = 0.3;
  [[nodiscard]] bool fresh() const noexcept {
    return head_age_s < max_input_age_s && base_age_s < max_input_age_s && hip_age_s < max_input_age_s;
  }
};

/// The base twist to command (base frame). The server's guard limits it afterwards.
using BasePlanFn = std::function<BaseTwist(const BasePlanInput&)>;

struct ServerOptions {
  double duration_s = 0.0;               ///< 0: until request_stop()
  std::filesystem::path recording;       ///< empty: no recording
  std::vector<std::filesystem::path> plugin_path;  ///< --plugin-path folders
  BasePlanFn plan_base;  ///< empty: the scene's <planner>, or without one the base holds still
  std::function<void(const ServerStatus&)> on_status;  ///< called from run()'s thread
  double status_interval_s = 0.5;
};

/// Why a run ended.
enum class RunEnd {
  Duration,       ///< ServerOptions::duration_s passed
  StopRequested,  ///< request_stop() (Ctrl-C)
  Fault,          ///< a plugin failed, refused to start, or the recording could not be written
};

/// A shared object at the run's end, as this rig rendered it (docs/shared-objects.md).
struct SharedObjectEnd {
  std::string name;
  std::uint32_t id = 0;
  std::uint32_t authority_rig = 0;
  bool held_here = false;  ///< this rig was its authority (ran its physics)
  Eigen::Vector3d p_W_start_m = Eigen::Vector3d::Zero();  ///< its origin at the start
  Eigen::Vector3d p_W_end_m = Eigen::Vector3d::Zero();    ///< and at the end
  double state_age_s = 0.0;  ///< of the state a replica rendered last (0 when held here)
};

struct ServerReport {
  ServerStatus status;  ///< at the end
  RunEnd ended_by = RunEnd::Fault;
  std::uint64_t missed_deadlines = 0;
  double tick_median_us = 0.0, tick_p99_us = 0.0, tick_p999_us = 0.0, tick_max_us = 0.0;
  std::uint64_t contact_ticks = 0;
  std::uint64_t proxy_budget_exhausted_ticks = 0;  ///< ticks whose proxy ran out of its work budget
  /// Ticks before the first base pose (no HIP, no force): a normal start, not a fault.
  std::uint64_t startup_ticks = 0;
  std::uint64_t stale_ticks = 0, fault_ticks = 0, hip_jumps = 0, clamped_ticks = 0;
  std::uint64_t base_commands = 0, base_stops = 0;  ///< commands sent; of them zero by a guard stop
  BaseStopCounts base_stops_by_cause;  ///< stop episodes by cause, and keep-out deflections
  std::uint64_t recording_rows = 0, recording_dropped = 0;
  std::vector<SharedObjectEnd> shared_objects;  ///< empty when the scene shares none
  SharingCounters sharing;                      ///< what the rig sent and received
  std::uint64_t link_dropped = 0;  ///< messages lost between the haptic thread and the link (queue full)
  bool zero_force_sent = false;  ///< the last device command was zero torque
  bool base_stop_sent = false;   ///< the last base command was zero (or there is no base)
  std::string haptic_scheduling;  ///< e.g. "SCHED_FIFO 80", or why real-time scheduling was refused
  /// Page faults the haptic thread took in its loop, plugin calls included: minor (the
  /// page was in memory) and major (read from the disk). Each is a wait inside a tick.
  long haptic_minor_page_faults = 0;
  long haptic_major_page_faults = 0;
  std::optional<std::string> error;  ///< why the run ended early
};

class HapticServer;

/// A server ready to run, and what its opening warned of.
struct OpenedServer {
  std::unique_ptr<HapticServer> server;  ///< never null
  Diagnostics warnings;  ///< the run goes on, but the user should know (a scene force limit the device lowers)
};

class HapticServer {
 public:
  /// Checks the scene (rig, <server>, <simulated_user>, one device; a mobile rig one tracker and
  /// at most one base, a desktop rig neither) and opens its plugins; every problem is a diagnostic at its scene line.
  /// `compiled` must outlive the server.
  [[nodiscard]] static Result<OpenedServer> open(const SceneDescription& scene, const CompiledScene& compiled,
                                                 ServerOptions options);
  ~HapticServer();
  HapticServer(const HapticServer&) = delete;
  HapticServer& operator=(const HapticServer&) = delete;

  /// Starts the plugins and threads, runs for the duration or until request_stop() or an
  /// error, then leaves everything stopped and closed (safe state). Call once.
  ServerReport run();
  /// From any thread or a signal handler.
  void request_stop() noexcept { stop_requested_.store(true, std::memory_order_relaxed); }

  /// What last_gasp() did, and the plugin call the dying thread was in.
  struct LastGasp {
    bool sent = false;              ///< run() was running and this call sent the zeros
    bool zero_torque_sent = false;  ///< the device took a zero command
    bool base_stop_sent = false;    ///< the base took a zero twist (or there is none)
    bool desktop = false;           ///< a desktop rig: there is no base to speak of
  };
  /// The plugin call in progress on the calling thread ("plugin 'x' (scene.xml:12)" and
  /// e.g. "display_write"), or nulls when none: which plugin a crash happened in. The
  /// strings live as long as the server. Async-signal-safe (reads a thread-local).
  [[nodiscard]] static std::pair<const char*, const char*> call_in_progress() noexcept;
  /// For a process about to die while run() runs (a plugin crashed, aborted, threw or
  /// called exit()), from the dying thread, in a signal handler if need be: ends the
  /// threads' loops, lets them reach their own safe state (at most 50 ms), then sends zero
  /// torque and a zero base twist directly through the plugins (the plugin whose call the
  /// dying thread is in last), and keeps run() from stopping or closing any plugin after.
  /// No lock, no allocation on success; only atomics, nanosleep and the plugins' own
  /// write calls. Once: a second call (or one outside run()) sends nothing.
  LastGasp last_gasp() noexcept;

  [[nodiscard]] const ServerSettings& settings() const noexcept;
  /// The host clock the server's plugins, report and recording read: seconds since the
  /// server opened.
  [[nodiscard]] double host_now_s() const noexcept;

 private:
  struct Impl;
  explicit HapticServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
  std::atomic<bool> stop_requested_{false};
};

}  // namespace mhd
