#pragma once
// The Force Dimension SDK's libdhd loaded at run time: the few documented C calls the
// forcedimension plugin makes (declared from the SDK's reference; the SDK is not a Debian
// package), its error codes, and one error line naming the library and how to install it
// when it is missing. The SDK speaks SI units: metres, m/s, newtons. The test fake of
// libdhd (tests/hardware/fakes/fake_dhd.cpp) implements the same calls.

#include <string>

namespace mhd_forcedimension {

namespace dhd {

constexpr int kOn = 1;
constexpr int kOff = 0;
/// dhdSetForce's non-error returns.
constexpr int kTimeGuard = 1;
constexpr int kMotorSaturated = 2;
/// dhdGetStatus: how many, and the two the plugin reads.
constexpr int kStatusCount = 16;
constexpr int kStatusForce = 5;
constexpr int kStatusForceOffCause = 14;
/// dhdSetWatchdog counts in these.
constexpr double kWatchdogTickS = 125e-6;

// dhdGetSystemType.
constexpr int kDelta3 = 63;
constexpr int kDelta6 = 64;
constexpr int kOmega3 = 33;
constexpr int kOmega33 = 34;
constexpr int kOmega33Left = 36;
constexpr int kOmega331 = 35;
constexpr int kOmega331Left = 37;
constexpr int kFalcon = 60;
constexpr int kSigma331 = 104;
constexpr int kSigma331Left = 105;
constexpr int kSigma33p = 106;
constexpr int kSigma33pLeft = 107;

// dhdErrorGetLast (the SDK's dhd_errors, in order).
constexpr int kErrorCom = 2;
constexpr int kErrorNoDriverFound = 4;
constexpr int kErrorNoDeviceFound = 5;
constexpr int kErrorNotAvailable = 6;
constexpr int kErrorTimeout = 7;
constexpr int kErrorDeviceNotReady = 12;
constexpr int kErrorDeviceInUse = 20;

}  // namespace dhd

struct DhdCalls {
  int (*dhdOpen)();
  int (*dhdOpenSerial)(int serial);
  int (*dhdClose)(char id);
  int (*dhdStop)(char id);
  int (*dhdGetSystemType)(char id);
  const char* (*dhdGetSystemName)(char id);
  int (*dhdEnableForce)(unsigned char on, char id);
  int (*dhdSetGravityCompensation)(int on, char id);
  int (*dhdSetWatchdog)(unsigned char ticks, char id);
  int (*dhdGetPosition)(double* x, double* y, double* z, char id);
  int (*dhdGetLinearVelocity)(double* vx, double* vy, double* vz, char id);
  unsigned int (*dhdGetButtonMask)(char id);
  int (*dhdGetStatus)(int status[dhd::kStatusCount], char id);
  int (*dhdSetForce)(double fx, double fy, double fz, char id);
  int (*dhdErrorGetLast)();
  const char* (*dhdErrorGetStr)(int error);
};

class DhdRuntime {
 public:
  /// dlopen(library) and every call; throws std::runtime_error naming the library, what
  /// the loader said and how to install the SDK.
  explicit DhdRuntime(const std::string& library);
  ~DhdRuntime();
  DhdRuntime(const DhdRuntime&) = delete;
  DhdRuntime& operator=(const DhdRuntime&) = delete;

  [[nodiscard]] const DhdCalls& calls() const noexcept { return calls_; }

 private:
  void* handle_ = nullptr;
  DhdCalls calls_{};
};

/// "<call>: DHD_ERROR_COM (2): <the SDK's text>; <what to do>" for the SDK's last error.
std::string describe_last_error(const DhdCalls& dhd, const char* call);

/// Why the device turned its forces off (dhdGetStatus' force-off cause), in words.
const char* force_off_cause(int cause) noexcept;

/// What a device type can do: the host clamps with it.
struct DeviceModel {
  const char* name;
  double max_force_N;
  double max_stiffness_N_per_m;
  double half_width_m[3];  ///< a box about the origin inside the translation workspace
};

/// The model of dhdGetSystemType's answer, nullptr for a type MHD does not know.
const DeviceModel* model_of(int system_type) noexcept;

}  // namespace mhd_forcedimension
