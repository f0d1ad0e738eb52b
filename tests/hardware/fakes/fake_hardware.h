#pragma once
// What the fakes of vendor libraries share (fake_hd.cpp for OpenHaptics, fake_dhd.cpp for
// the Force Dimension SDK, fake_isense.cpp for the InterSense SDK): the environment that
// configures them, the log of what the hardware received, the simulated hand that holds
// the tool, and the clock.
//
// Environment (read once, when the fake is first called):
//   MHD_FAKE_LOG            the log file (none: no log)
//   MHD_FAKE_FAULT          none|unplugged|error_every_call|comm_error|nan_position|
//                           servo_stall|warm_motors|needs_manual_calibration|needs_update|
//                           frozen_timestamp|old_library|hang|dropout
//                           (servo_stall to needs_update: OpenHaptics only; the last
//                           four: InterSense only; dropout: the stations are lost for 1 s)
//   MHD_FAKE_FAULT_AFTER_S  when comm_error, nan_position, servo_stall, warm_motors,
//                           frozen_timestamp, hang and dropout strike, after force output was first
//                           enabled (a tracker: after its first read) (default 1)
//   MHD_FAKE_MAX_FORCE_N    the nominal maximum force the device reports (default 3.3)
//   MHD_FAKE_WORKSPACE_MM   the usable workspace "minx miny minz maxx maxy maxz"
//                           (OpenHaptics; the Force Dimension SDK reports none)
//   MHD_FAKE_MODEL          the Force Dimension device: omega3 (default) or delta3
// Log: "t_s,event,a,b,c" lines, each written at once with write(2), so a process that dies
// leaves the log whole. t_s is the steady clock.

#include <array>
#include <atomic>
#include <string>

namespace mhd::fake {

enum class Fault {
  None, Unplugged, ErrorEveryCall, CommError, NanPosition, ServoStall, WarmMotors, NeedsManualCalibration,
  NeedsUpdate, FrozenTimestamp, OldLibrary, Hang, Dropout
};

double now_s();

struct Config {
  Fault fault = Fault::None;
  double fault_after_s = 1.0;
  double max_force_N = 3.3;
  std::array<double, 6> workspace_mm{-80, -60, -35, 80, 60, 35};
  std::string model = "omega3";
  static Config from_environment();
};

class HardwareLog {
 public:
  HardwareLog();  ///< opens MHD_FAKE_LOG, writes the header
  ~HardwareLog();
  HardwareLog(const HardwareLog&) = delete;
  HardwareLog& operator=(const HardwareLog&) = delete;
  void add(const char* event, double a = 0, double b = 0, double c = 0) const { add_at(now_s(), event, a, b, c); }
  void add_at(double t_s, const char* event, double a = 0, double b = 0, double c = 0) const;

 private:
  int fd_ = -1;
};

/// A hand holding the tool on a spring: the target goes 50 mm down from 20 mm above the
/// device's origin and back every 2 s, the motors push with the force they give.
/// Positions in metres, in a frame whose `up` axis is the given index.
class Hand {
 public:
  explicit Hand(int up_axis) : up_(up_axis) { p_m_[static_cast<std::size_t>(up_)] = 0.02; }
  void step(double dt_s, const std::array<double, 3>& motor_force_N);
  [[nodiscard]] const std::array<double, 3>& p_m() const { return p_m_; }
  [[nodiscard]] const std::array<double, 3>& v_m_s() const { return v_m_s_; }

 private:
  int up_;
  double t_s_ = 0.0;
  std::array<double, 3> p_m_{};
  std::array<double, 3> v_m_s_{};
};

/// When the configured mid-run fault strikes: fault_after_s after force output was first on.
class FaultClock {
 public:
  void force_enabled() {
    double none = 0.0;
    enabled_at_s_.compare_exchange_strong(none, now_s());
  }
  [[nodiscard]] bool struck(double after_s) const {
    const double at = enabled_at_s_.load();
    return at > 0.0 && now_s() - at >= after_s;
  }

 private:
  std::atomic<double> enabled_at_s_{0.0};
};

/// What every fake device holds: its configuration, its log and when its fault strikes.
struct FakeBase {
  Config config = Config::from_environment();
  HardwareLog log;
  FaultClock fault_clock;
  [[nodiscard]] bool struck() const { return fault_clock.struck(config.fault_after_s); }
};

/// |f| of a 3-vector.
double norm(const std::array<double, 3>& f);

}  // namespace mhd::fake
