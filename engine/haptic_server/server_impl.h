#pragma once
// The haptic server's shared state (private to engine/haptic_server): the plugins, the
// hand-offs between the threads, the counters, and the run's end. Each thread's body
// lives in its own file (haptic_thread.cpp, io_thread.cpp, planner_thread.cpp,
// display_thread.cpp, recorder_thread.cpp); opening, run() and the last gasp in
// haptic_server.cpp.

#include "haptic_server/haptic_server.h"
#include "haptic_server/head_state.h"
#include "haptic_server/opened_plugin.h"
#include "haptic_server/status_counters.h"
#include "haptic_server/tick_histogram.h"
#include "kinematics/rig.h"
#include "planner/lift_planner.h"
#include "plugin_host/host_services.h"
#include "plugin_host/plugin_error.h"
#include "realtime/periodic_timer.h"
#include "realtime/seqlock.h"
#include "realtime/spsc_ring.h"
#include "realtime/thread_page_faults.h"
#include "realtime/triple_buffer.h"
#include "realtime/wake_event.h"
#include "recording/csv_recording.h"
#include "safety/base_command_guard.h"
#include "safety/force_safety.h"

#include <Eigen/Core>

#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace mhd {

class HapticTick;
class PluginWatchdog;
struct HapticTickOutput;

struct HapticServer::Impl {
  struct BaseSensorSample {
    double t_s = 0.0;
    Pose X_is900_base_sensor = Pose::Identity();
  };
  struct BaseCommandEvent {
    double t_s = 0.0;
    BaseTwist twist_B;
  };
  /// State the haptic thread publishes each tick (for the planner and the displays).
  struct HapticSnapshot {
    double t_s = 0.0;
    bool valid = false;  ///< a HIP is known
    Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
    Eigen::Vector3d proxy_W_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d force_W_N = Eigen::Vector3d::Zero();
    bool in_contact = false;
    BasePose base;
  };
  /// The last gasp's claim on the plugins: run() arms it while plugins may be driven, and
  /// exactly one of run() (to stop and close them) and a dying thread (to send the zeros) wins.
  enum GaspState : int { kGaspIdle, kGaspArmed, kGaspSending, kGaspDone };

  const CompiledScene& scene;
  ServerSettings settings;
  ServerOptions options;
  Rig rig;
  HostServices host;
  std::vector<OpenedPlugin> plugins;  // device first, then tracker, base, displays
  OpenedPlugin* device = nullptr;
  OpenedPlugin* tracker = nullptr;  ///< null on a desktop rig
  OpenedPlugin* base = nullptr;
  std::vector<OpenedPlugin*> displays;
  OpenedPlugin* link = nullptr;  ///< the link to the rigs sharing objects; null when none

  // Hand-offs.
  realtime::SpscRing<BaseSensorSample> base_samples{512};
  realtime::SpscRing<BaseCommandEvent> commands_to_haptic{64};
  realtime::SpscRing<RecordingRow> recording_rows{1 << 14};
  realtime::TripleBuffer<HapticSnapshot> snapshot_for_planner;
  realtime::TripleBuffer<HapticSnapshot> snapshot_for_display;
  realtime::TripleBuffer<HapticSnapshot> snapshot_for_io;  ///< the base pose the guard judges
  SharedHead head;                                  ///< io -> planner, display, recorder
  realtime::TripleBuffer<BaseTwist> planned_command;  ///< planner -> io
  realtime::TripleBuffer<FloorView> floor_view;       ///< io -> planner: the other rigs on the floor
  realtime::SpscRing<LinkMessage> link_to_haptic{1024};    ///< link -> haptic: the other rigs' messages
  realtime::SpscRing<LinkMessage> link_from_haptic{1024};  ///< haptic -> link: this rig's
  std::atomic<std::uint64_t> link_dropped{0};              ///< either ring full
  realtime::WakeEvent base_sample_arrived;  ///< io -> haptic: start the tick now
  bool tick_on_tracker_sample = false;      ///< set by run(): the tracker can wake the io thread

  // Status, written by the haptic, io and planner threads, read by run().
  StatusCounters status_counters;
  // For the report only.
  std::atomic<std::uint64_t> missed{0}, contact_ticks{0}, proxy_budget_exhausted_ticks{0}, recording_dropped{0};
  std::atomic<std::uint64_t> base_commands{0}, base_stops{0};
  realtime::TripleBuffer<BaseStopCounts> base_stop_counts;  ///< the guard's, by cause (io -> run())
  std::atomic<double> base_sample_newest_t_s{-std::numeric_limits<double>::infinity()};  ///< for the planner
  /// The lift as the base last reported it (io -> haptic, planner): height (NaN until
  /// the first report), vertical speed, and when it was measured.
  realtime::Seqlock<3> lift_reading{{std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}};
  std::atomic<double> planned_lift_vmps{0.0};  ///< planner -> io

  std::atomic<bool> stop{false};
  std::atomic<int> gasp_state{kGaspIdle};
  std::atomic<bool> recorder_stop{false};  ///< set after the haptic thread has ended
  std::atomic<int> running_threads{0};     ///< server threads not yet ended (not the recorder)
  /// Threads that ended without returning (pthread_exit in a plugin call): their safe
  /// state (the haptic thread's zero torque, the io thread's base stop) is run()'s to send.
  std::atomic<bool> haptic_thread_vanished{false}, io_thread_vanished{false};
  /// A thread never came back from a plugin call: this Impl (and the plugin's library)
  /// must outlive it, so it is never destroyed.
  bool abandoned = false;
  std::mutex error_mutex;
  std::optional<std::string> error;

  // Filled by the threads before they end.
  TickHistogram tick_histogram;
  ForceSafetyCounters safety_counters;
  std::uint64_t startup_ticks = 0;  ///< ticks before the first base pose (HapticTick::startup_ticks)
  /// The shared objects as the haptic thread left them (it allocates nothing: run()'s
  /// thread makes the report's entries of them).
  struct SharedObjectFinal {
    int object = -1;
    std::uint32_t id = 0, authority_rig = 0;
    bool held_here = false;
    Eigen::Vector3d p_W_end_m = Eigen::Vector3d::Zero();
    double state_age_s = 0.0;
  };
  std::array<SharedObjectFinal, RigSharing::kMaxObjects> shared_final{};
  int shared_final_count = 0;
  SharingCounters sharing_counters;
  std::optional<CsvRecording> recording;  ///< opened by run(), written by the recorder thread
  bool zero_force_sent = false;
  std::atomic<bool> base_stop_sent{false};  ///< by the io thread, or run()'s when the io thread is stuck
  std::string scheduling;  ///< the haptic thread's, as obtained
  realtime::PageFaults haptic_page_faults;  ///< taken by the haptic thread's loop
  std::uint64_t recording_rows_written = 0;

  Impl(const CompiledScene& s, ServerSettings st, ServerOptions o, Rig r)
      : scene(s), settings(std::move(st)), options(std::move(o)), rig(std::move(r)) {}

  static std::string plugin_failure(const PluginDescription& d, const PluginError& e) {
    return Diagnostic{d.where, e.to_string()}.to_string();
  }

  /// A server thread ended without returning from its body: the run ends, naming the
  /// plugin call it was last in.
  void thread_vanished(void (Impl::*body)(), const char* thread_name);

  void fail(std::string message) {
    {
      const std::lock_guard lock(error_mutex);
      if (!error) error = std::move(message);
    }
    stop.store(true);
  }

  /// True when the call failed (the run is ending); `what` says which call.
  template <typename Result>
  bool check(const Result& result, const OpenedPlugin& plugin) {
    if (result.ok()) return false;
    fail(plugin_failure(plugin.description, result.error()));
    return true;
  }

  /// "plugin 'name': what", for a fault found in what a plugin returned.
  static std::string plugin_said(const OpenedPlugin& plugin, const std::string& what) {
    return "plugin '" + plugin.description.name + "': " + what;
  }

  bool deactivated(PluginCallStatus status, const OpenedPlugin& plugin, const char* call) {
    if (status != PluginCallStatus::Deactivate) return false;
    fail(Diagnostic{plugin.description.where,
                    "plugin '" + plugin.description.name + "': " + call + " asked to be stopped (MHD_DEACTIVATE)"}
             .to_string());
    return true;
  }

  /// Sends the base a zero twist (under its call claim) and notes whether it took it
  /// (io_thread.cpp).
  void stop_base();

  // Running (haptic_server.cpp), in run()'s order.
  std::vector<OpenedPlugin*> start_plugins();
  void open_recording();
  void run_threads(ServerReport& report, double t0_s, const std::atomic<bool>& stop_requested);
  void spawn(std::vector<std::thread>& threads, void (Impl::*body)(), const char* name);
  void supervise(ServerReport& report, double t0_s, const std::atomic<bool>& stop_requested, PluginWatchdog& watchdog,
                 const std::vector<OpenedPlugin*>& watched);
  void watch_calls(PluginWatchdog& watchdog, const std::vector<OpenedPlugin*>& watched, double now_s);
  void join_threads(std::vector<std::thread>& threads, PluginWatchdog& watchdog,
                    const std::vector<OpenedPlugin*>& watched);
  void read_final_tracker_counts();
  void stop_and_close(const std::vector<OpenedPlugin*>& start_order);
  void fill_report(ServerReport& report, double elapsed_s);

  // Opening (haptic_server.cpp): the plugins in `order`, then the settings that depend on
  // the device's own report. Each returns the problems at their scene lines.
  Diagnostics open_plugins(const std::vector<const PluginDescription*>& order);
  Diagnostics fit_to_device(const SceneDescription& description, const PluginDescription& described, bool scene_plans,
                            Diagnostics& warnings);

  // Each thread's body, in its own file (<name>.cpp).
  void haptic_thread();
  // The haptic thread's steps, in tick order; a false return ends the run.
  void drain_into(HapticTick& tick);
  bool read_device(double t_s, const DeviceInfo& info, Eigen::Vector3d& p_D_tool_m);
  bool write_device(double t_s, const HapticTickOutput& out);
  void publish(double t_s, const HapticTickOutput& out);
  void record(double t_s, double dt_s, const HapticTickOutput& out);
  void count(const HapticTickOutput& out, const realtime::TimerStats& timer);
  /// Shared objects (link_thread.cpp): what the link brought into the tick, and the
  /// tick's messages out to the link. No lock, no allocation.
  void receive_shared(HapticTick& tick, double t_s);
  void send_shared(const HapticTick& tick);
  void note_shared_objects(const HapticTick& tick, double t_s);

  void link_thread();

  void io_thread();
  // The io thread's steps, in period order (io_thread.cpp); a false return (or nullopt)
  // ends the run.
  struct IoThreadState;
  bool take_samples_until_deadline(IoThreadState& io, const realtime::PeriodicTimer& timer);
  bool simulate_io_plugins(double t_s);
  std::optional<std::size_t> read_tracker(IoThreadState& io);
  bool take_sample(IoThreadState& io, const TrackerSample& s, double read_at_s, bool& base_sample);
  bool read_tracker_counters(IoThreadState& io, double t_s);
  bool read_base(IoThreadState& io, double t_s);
  void take_odometry(IoThreadState& io, const BaseState& base_state);
  bool take_lift(const BaseState& base_state);
  /// The lift's height at t_s, carried on from its last reading at that reading's speed
  /// for at most one io period (NaN before the first reading).
  double lift_m_at(double t_s) const noexcept;
  double plan_lift(const LiftPlanner& planner, const HapticSnapshot& snap, double hip_age_s) const;
  BaseGuardDecision guard_plan(IoThreadState& io, double t_s, bool& new_plan);
  bool send_base_command(IoThreadState& io, double t_s, bool new_plan, const BaseGuardDecision& guarded);
  void planner_thread();
  void display_thread();
  void recorder_thread();
};

}  // namespace mhd
