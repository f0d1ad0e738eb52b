// A fake of the Force Dimension SDK's libdhd for the forcedimension plugin's tests, loaded
// through the real dlopen path in its place (fake_hardware.h: its configuration and log).
// It implements the documented calls the plugin makes. Like the SDK's, they are
// synchronous: the simulated omega.3 advances when the tool is read, and the motors give
// the force of the last dhdSetForce until the firmware watchdog fires. Its log's events:
//   open | gravity_on | watchdog | force_on | force_off | stop | close
//   force       each dhdSetForce: the force the motors gave (zero while output is off)
//   timeout     the firmware watchdog: no force for the armed time; t_s is when it fired.
//               Forces then stay off (dhdGetStatus says why) until enabled again
//   over_limit  a force above the nominal maximum was asked (a: its magnitude); clamped
//   fault       a call failed (a: the SDK's error code)
#include "fake_hardware.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <mutex>

using mhd::fake::Fault;

namespace {

constexpr int kOmega3 = 33;
constexpr int kDelta3 = 63;
constexpr int kErrorCom = 2;
constexpr int kErrorNoDeviceFound = 5;
constexpr int kError = 1;
constexpr int kStatusForce = 5;
constexpr int kStatusForceOffCause = 14;
constexpr int kForceOffWatchdog = 3;
constexpr int kStatusCount = 16;

struct Device : mhd::fake::FakeBase {
  std::mutex mutex;  // the SDK's calls may come from several threads (the last gasp's)

  int last_error = 0;
  bool open = false;
  bool force_output = false;
  bool comm_lost = false;
  double watchdog_s = 0.0;
  double last_force_s = 0.0;
  bool watchdog_fired = false;
  int force_off_cause = 0;
  double last_step_s = 0.0;
  mhd::fake::Hand hand{2};  // the SDK: z up
  std::array<double, 3> motor_force_N{};

  /// Every call: the failures configured, then the firmware watchdog. False: the call fails.
  bool call() {
    if (config.fault == Fault::ErrorEveryCall) return fail(kError);
    if (config.fault == Fault::CommError && struck() && !comm_lost) {
      comm_lost = true;
      motor_force_N = {};
      log.add("force");  // the controller cuts the motors when its USB link drops
    }
    if (comm_lost) return fail(kErrorCom);
    const double t = mhd::fake::now_s();
    if (force_output && watchdog_s > 0.0 && !watchdog_fired && t - last_force_s > watchdog_s) {
      log.add_at(last_force_s + watchdog_s, "timeout");
      motor_force_N = {};
      watchdog_fired = true;
      force_output = false;  // the firmware turns forces off until they are enabled again
      force_off_cause = kForceOffWatchdog;
    }
    return true;
  }
  bool fail(int code) {
    if (last_error != code) log.add("fault", code);
    last_error = code;
    return false;
  }
  void step_hand() {
    const double t = mhd::fake::now_s();
    if (last_step_s > 0.0) hand.step(std::min(t - last_step_s, 0.005), motor_force_N);
    last_step_s = t;
  }
};

Device& device() {
  static Device d;
  return d;
}

}  // namespace

#define FAKE_DHD_EXPORT extern "C" __attribute__((visibility("default")))

FAKE_DHD_EXPORT int dhdOpen() {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (d.config.fault == Fault::Unplugged) {
    d.fail(kErrorNoDeviceFound);
    return -1;
  }
  if (!d.call()) return -1;
  d.open = true;
  d.log.add("open");
  return 0;
}

FAKE_DHD_EXPORT int dhdOpenSerial(int /*serial*/) { return dhdOpen(); }

FAKE_DHD_EXPORT int dhdClose(char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  d.open = false;
  d.log.add("close");
  return 0;
}

FAKE_DHD_EXPORT int dhdStop(char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  d.force_output = false;
  d.motor_force_N = {};
  d.log.add("stop");
  return 0;
}

FAKE_DHD_EXPORT int dhdGetSystemType(char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (!d.call()) return -1;
  return d.config.model == "delta3" ? kDelta3 : kOmega3;
}

FAKE_DHD_EXPORT const char* dhdGetSystemName(char /*id*/) {
  return device().config.model == "delta3" ? "delta.3 (fake libdhd)" : "omega.3 (fake libdhd)";
}

FAKE_DHD_EXPORT int dhdEnableForce(unsigned char on, char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (on == 0) {  // always honoured: the firmware takes it even with the link failing
    d.force_output = false;
    d.motor_force_N = {};
    d.log.add("force_off");
    return 0;
  }
  if (!d.call()) return -1;
  d.force_output = true;
  d.force_off_cause = 0;
  d.last_force_s = mhd::fake::now_s();
  d.fault_clock.force_enabled();
  d.log.add("force_on");
  return 0;
}

FAKE_DHD_EXPORT int dhdSetGravityCompensation(int /*on*/, char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (!d.call()) return -1;
  d.log.add("gravity_on");
  return 0;
}

FAKE_DHD_EXPORT int dhdSetWatchdog(unsigned char ticks, char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (!d.call()) return -1;
  d.watchdog_s = ticks * 125e-6;
  d.log.add("watchdog", d.watchdog_s);
  return 0;
}

FAKE_DHD_EXPORT int dhdGetPosition(double* x, double* y, double* z, char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (!d.call()) return -1;
  d.step_hand();
  *x = d.hand.p_m()[0];
  *y = d.hand.p_m()[1];
  *z = d.hand.p_m()[2];
  if (d.config.fault == Fault::NanPosition && d.struck()) {
    *z = std::numeric_limits<double>::quiet_NaN();
  }
  return 0;
}

FAKE_DHD_EXPORT int dhdGetLinearVelocity(double* vx, double* vy, double* vz, char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (!d.call()) return -1;
  *vx = d.hand.v_m_s()[0];
  *vy = d.hand.v_m_s()[1];
  *vz = d.hand.v_m_s()[2];
  return 0;
}

FAKE_DHD_EXPORT int dhdGetStatus(int status[kStatusCount], char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (!d.call()) return -1;
  std::fill(status, status + kStatusCount, 0);
  status[kStatusForce] = d.force_output ? 1 : 0;
  status[kStatusForceOffCause] = d.force_off_cause;
  return 0;
}

FAKE_DHD_EXPORT unsigned int dhdGetButtonMask(char /*id*/) { return 0; }

FAKE_DHD_EXPORT int dhdSetForce(double fx, double fy, double fz, char /*id*/) {
  Device& d = device();
  const std::lock_guard lock(d.mutex);
  if (!d.call()) return -1;
  std::array<double, 3> f{fx, fy, fz};
  if (const double magnitude = mhd::fake::norm(f); magnitude > d.config.max_force_N * (1.0 + 1e-9)) {
    d.log.add("over_limit", magnitude);
    for (double& c : f) c *= d.config.max_force_N / magnitude;
  }
  if (!d.force_output) f = {};
  d.motor_force_N = f;
  d.last_force_s = mhd::fake::now_s();
  d.watchdog_fired = false;
  d.log.add("force", f[0], f[1], f[2]);
  return 0;
}

FAKE_DHD_EXPORT int dhdErrorGetLast() { return device().last_error; }

FAKE_DHD_EXPORT const char* dhdErrorGetStr(int error) {
  return error == kErrorCom ? "communication error between the host and the device" : "error";
}
