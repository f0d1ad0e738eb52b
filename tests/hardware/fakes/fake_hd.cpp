// A fake of OpenHaptics' libHD for the openhaptics plugin's tests, loaded through the real
// dlopen path in its place (fake_hardware.h: its configuration and log). It implements the
// documented HDAPI calls the plugin makes, with a servo thread at 1 kHz and a simulated
// device behind them. Its log's events:
//   init | calibrated | scheduler_start | force_on | force_off | scheduler_stop | device_disabled
//   force       each servo frame: the force the motors gave (zero while output is off)
//   timeout     the device's own watchdog: no frame for kWatchdogS; t_s is when it fired
//   over_limit  a force above the nominal maximum was set (a: its magnitude); clamped
//   fault       the driver raised an error (a: its code)
#include "device/openhaptics/hd_types.h"
#include "fake_hardware.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

using namespace mhd_openhaptics;
using mhd::fake::Fault;

namespace {

constexpr double kWatchdogS = 0.02;
constexpr double kMmPerM = 1000.0;
/// The joint angles are a stand-in that moves with the tool; the gimbal stands still.
constexpr double kJointRadPerM = 10.0;
constexpr std::array<double, 3> kGimbalAngles_rad{0.1, 0.2, 0.3};

/// The simulated device and the driver's state.
struct Device : mhd::fake::FakeBase {
  std::mutex errors_mutex;
  std::vector<HDErrorInfo> errors;

  std::atomic<bool> force_output{false};
  bool calibrated = config.fault != Fault::NeedsUpdate;

  // Touched with callbacks_mutex held (the servo thread, or a synchronous call).
  mhd::fake::Hand hand{1};  // HDAPI: y up
  std::array<double, 3> set_force_N{};
  std::array<double, 3> motor_force_N{};
  double last_frame_s = 0.0;
  bool comm_lost = false;
  bool watchdog_fired = false;

  std::mutex callbacks_mutex;
  std::map<HDSchedulerHandle, std::pair<HDSchedulerCallback, void*>> callbacks;
  HDSchedulerHandle next_handle = 1;
  std::atomic<bool> running{false};
  std::thread servo;

  Device() = default;
  // A process that ends without hdStopScheduler (exit() with the plugin left open): the
  // driver's servo thread ends with it.
  ~Device() {
    if (running.exchange(false)) servo.join();
  }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  void raise(HDerror code, int internal = 0) {
    log.add("fault", code);
    const std::lock_guard lock(errors_mutex);
    errors.push_back(HDErrorInfo{code, internal, 0});
  }
  void every_call() {
    if (config.fault == Fault::ErrorEveryCall) raise(hd::kDeviceFault, 99);
  }

  /// The device's own command watchdog: no frame for kWatchdogS, zero force.
  void fire_watchdog_if_due(double t) {
    if (watchdog_fired || t - last_frame_s <= kWatchdogS) return;
    log.add_at(last_frame_s + kWatchdogS, "timeout");
    motor_force_N = {};
    watchdog_fired = true;
  }

  void servo_loop() {
    last_frame_s = mhd::fake::now_s();
    auto next = std::chrono::steady_clock::now();
    while (running.load()) {
      next += std::chrono::milliseconds(1);
      std::this_thread::sleep_until(next);
      const std::lock_guard lock(callbacks_mutex);
      const double t = mhd::fake::now_s();
      fire_watchdog_if_due(t);
      if (config.fault == Fault::ServoStall && struck()) continue;  // the driver hangs; the device's timer does not
      hand.step(std::min(t - last_frame_s, 0.005), motor_force_N);
      last_frame_s = t;
      watchdog_fired = false;
      for (auto it = callbacks.begin(); it != callbacks.end();) {
        it = it->second.first(it->second.second) == hd::kCallbackDone ? callbacks.erase(it) : std::next(it);
      }
    }
  }

  void end_frame() {
    if (config.fault == Fault::CommError && struck() && !comm_lost) {
      comm_lost = true;
      raise(hd::kCommError, 7);
    }
    std::array<double, 3> f = set_force_N;
    if (const double magnitude = mhd::fake::norm(f); magnitude > config.max_force_N * (1.0 + 1e-9)) {
      log.add("over_limit", magnitude);
      raise(hd::kExceededMaxForce);
      for (double& c : f) c *= config.max_force_N / magnitude;
    }
    if (!force_output.load() || comm_lost) f = {};
    motor_force_N = f;
    log.add("force", f[0], f[1], f[2]);
  }
};

Device& device() {
  static Device d;
  return d;
}

}  // namespace

#define FAKE_HD_EXPORT extern "C" __attribute__((visibility("default")))

FAKE_HD_EXPORT HHD hdInitDevice(const char* /*config_name*/) {
  Device& d = device();
  d.every_call();
  if (d.config.fault == Fault::Unplugged) {
    d.raise(hd::kCommError, 3);
    return hd::kInvalidHandle;
  }
  d.log.add("init");
  return 0;
}

FAKE_HD_EXPORT void hdDisableDevice(HHD /*device*/) { device().log.add("device_disabled"); }
FAKE_HD_EXPORT void hdMakeCurrentDevice(HHD /*device*/) { device().every_call(); }

FAKE_HD_EXPORT HDErrorInfo hdGetError() {
  Device& d = device();
  const std::lock_guard lock(d.errors_mutex);
  if (d.errors.empty()) return HDErrorInfo{hd::kSuccess, 0, 0};
  const HDErrorInfo e = d.errors.back();
  d.errors.pop_back();
  return e;
}

FAKE_HD_EXPORT const char* hdGetErrorString(HDerror code) {
  return code == hd::kCommError ? "Communication error" : "Device error";
}

FAKE_HD_EXPORT void hdBeginFrame(HHD /*device*/) { device().every_call(); }
FAKE_HD_EXPORT void hdEndFrame(HHD /*device*/) { device().end_frame(); }

FAKE_HD_EXPORT void hdEnable(HDenum capability) {
  Device& d = device();
  d.every_call();
  if (capability != hd::kForceOutput) return;
  d.force_output.store(true);
  d.fault_clock.force_enabled();
  d.log.add("force_on");
}

FAKE_HD_EXPORT void hdDisable(HDenum capability) {
  Device& d = device();
  if (capability != hd::kForceOutput) return;
  d.force_output.store(false);
  d.log.add("force_off");
}

FAKE_HD_EXPORT void hdGetDoublev(HDenum parameter, double* values) {
  Device& d = device();
  d.every_call();
  const auto mm = [](const std::array<double, 3>& v_m, double* out) {
    for (std::size_t i = 0; i < 3; ++i) out[i] = v_m[i] * kMmPerM;
  };
  switch (parameter) {
    case hd::kCurrentPosition:
      mm(d.hand.p_m(), values);
      if (d.config.fault == Fault::NanPosition && d.struck()) values[1] = std::numeric_limits<double>::quiet_NaN();
      return;
    case hd::kCurrentVelocity:
      mm(d.hand.v_m_s(), values);
      return;
    case hd::kCurrentTransform:
      std::fill(values, values + 16, 0.0);
      values[0] = values[5] = values[10] = values[15] = 1.0;
      mm(d.hand.p_m(), values + 12);
      return;
    case hd::kUsableWorkspaceDimensions:
      std::copy(d.config.workspace_mm.begin(), d.config.workspace_mm.end(), values);
      return;
    case hd::kNominalMaxForce:
      values[0] = d.config.max_force_N;
      return;
    case hd::kNominalMaxStiffness:
      values[0] = 1.26;  // a Touch's, N/mm
      return;
    case hd::kMotorTemperature:
      std::fill(values, values + hd::kMaxMotors, d.config.fault == Fault::WarmMotors && d.struck() ? 0.95 : 0.2);
      return;
    case hd::kCurrentJointAngles:  // a stand-in that moves with the tool: 10 rad per metre
      for (std::size_t i = 0; i < 3; ++i) values[i] = d.hand.p_m()[i] * kJointRadPerM;
      return;
    case hd::kCurrentGimbalAngles:
      std::copy(kGimbalAngles_rad.begin(), kGimbalAngles_rad.end(), values);
      return;
    default:
      d.raise(hd::kInvalidEnum);
  }
}

FAKE_HD_EXPORT void hdGetIntegerv(HDenum parameter, int* values) {
  Device& d = device();
  d.every_call();
  switch (parameter) {
    case hd::kCurrentButtons:
      values[0] = 0;
      return;
    case hd::kInputDof:
      values[0] = 6;
      return;
    case hd::kOutputDof:
      values[0] = 3;
      return;
    case hd::kCalibrationStyle:
      values[0] = 1 << 2;  // inkwell
      return;
    default:
      d.raise(hd::kInvalidEnum);
  }
}

FAKE_HD_EXPORT const char* hdGetString(HDenum parameter) {
  device().every_call();
  return parameter == hd::kDeviceModelType ? "Touch (fake libHD)" : "";
}

FAKE_HD_EXPORT void hdSetDoublev(HDenum parameter, const double* values) {
  Device& d = device();
  if (parameter != hd::kCurrentForce) {
    d.raise(hd::kInvalidEnum);
    return;
  }
  std::copy(values, values + 3, d.set_force_N.begin());
}

FAKE_HD_EXPORT int hdCheckCalibration() {
  Device& d = device();
  d.every_call();
  if (d.config.fault == Fault::NeedsManualCalibration) return hd::kCalibrationNeedsManualInput;
  return d.calibrated ? hd::kCalibrationOk : hd::kCalibrationNeedsUpdate;
}

FAKE_HD_EXPORT void hdUpdateCalibration(HDenum /*style*/) {
  Device& d = device();
  d.calibrated = true;
  d.log.add("calibrated");
}

FAKE_HD_EXPORT void hdStartScheduler() {
  Device& d = device();
  d.every_call();
  if (d.running.exchange(true)) return;
  d.log.add("scheduler_start");
  d.servo = std::thread([&d] { d.servo_loop(); });
}

FAKE_HD_EXPORT void hdStopScheduler() {
  Device& d = device();
  if (!d.running.exchange(false)) return;
  d.servo.join();
  d.log.add("scheduler_stop");
}

FAKE_HD_EXPORT HDSchedulerHandle hdScheduleAsynchronous(HDSchedulerCallback callback, void* user_data,
                                                        unsigned short /*priority*/) {
  Device& d = device();
  const std::lock_guard lock(d.callbacks_mutex);
  const HDSchedulerHandle handle = d.next_handle++;
  d.callbacks[handle] = {callback, user_data};
  return handle;
}

FAKE_HD_EXPORT void hdScheduleSynchronous(HDSchedulerCallback callback, void* user_data,
                                          unsigned short /*priority*/) {
  // Run in the caller's thread, between servo frames: what a synchronous call guarantees.
  Device& d = device();
  const std::lock_guard lock(d.callbacks_mutex);
  while (callback(user_data) != hd::kCallbackDone) {
  }
}

FAKE_HD_EXPORT void hdUnschedule(HDSchedulerHandle handle) {
  Device& d = device();
  const std::lock_guard lock(d.callbacks_mutex);
  d.callbacks.erase(handle);
}
