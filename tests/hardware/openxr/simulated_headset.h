#pragma once
// What stands behind the fake OpenXR runtime: a headset worn by a user who stands still
// with a slight sway, its faults, and the log of what the runtime was asked.
//
// Environment (read when the instance is created):
//   MHD_FAKE_LOG            the log file (none: no log); "t_s,event,a,b,c" lines, each
//                           written at once with write(2), t_s the steady clock, as the
//                           other fakes' (tests/hardware/fakes/fake_hardware.h)
//   MHD_FAKE_FAULT          none|tracking_lost|nan_pose|session_lost|no_system|hang
//                           (hang: xrLocateSpace never returns, a runtime stuck in a lock)
//   MHD_FAKE_FAULT_AFTER_S  when tracking_lost, nan_pose, session_lost and hang strike, after
//                           the session began (default 1)
//   MHD_FAKE_HEAD_M         the head's mean position "x y z" in the base space (default
//                           the POMHI rig's tracker frame: 1.65 m up, 0.9 m in front of
//                           the world origin)
// Events logged: create_instance, get_system, create_session, begin_session, locate
// (a: the location flags, b: 1 when the pose is finite), request_exit, end_session,
// destroy_space, destroy_session, destroy_instance.

#include <openxr/openxr.h>

#include <array>
#include <string>

namespace mhd::fake_openxr {

enum class Fault { None, TrackingLost, NanPose, SessionLost, NoSystem, Hang };

double now_s();

class SimulatedHeadset {
 public:
  SimulatedHeadset();  ///< reads the environment, opens the log
  ~SimulatedHeadset();
  SimulatedHeadset(const SimulatedHeadset&) = delete;
  SimulatedHeadset& operator=(const SimulatedHeadset&) = delete;

  [[nodiscard]] Fault fault() const noexcept { return fault_; }
  void began() noexcept { began_at_s_ = now_s(); }
  /// Whether the configured mid-run fault has struck.
  [[nodiscard]] bool struck() const noexcept;
  /// The head in the base space now, as the runtime reports it (flags cleared or the pose
  /// non-finite once a fault struck).
  [[nodiscard]] XrSpaceLocation locate() const noexcept;

  void log(const char* event, double a = 0, double b = 0, double c = 0) const noexcept;

 private:
  Fault fault_ = Fault::None;
  double fault_after_s_ = 1.0;
  std::array<double, 3> p_head_m_{-0.9, 0.0, 0.974};
  double began_at_s_ = -1.0;
  int log_fd_ = -1;
};

}  // namespace mhd::fake_openxr
