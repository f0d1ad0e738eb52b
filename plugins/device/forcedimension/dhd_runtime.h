#pragma once
// The Force Dimension SDK's libdhd loaded at run time: the few documented C calls the
// forcedimension plugin makes (declared from the SDK's reference; the SDK is not a Debian
// package), its error codes, and one error line naming the library and how to install it
// when it is missing. The SDK speaks SI units: metres, m/s, newtons. The test fake of
// libdhd (tests/hardware/fakes/fake_dhd.cpp) implements the same calls.

#include "vendor_library.h"

#include <memory>
#include <string>

namespace mhd_forcedimension {

namespace dhd {

constexpr int kOn = 1;
constexpr int kOff = 0;
/// dhdGetStatus: how many, and the two the plugin reads.
constexpr int kStatusCount = 16;
constexpr int kStatusForce = 5;
constexpr int kStatusForceOffCause = 14;
/// dhdSetWatchdog counts in these.
constexpr double kWatchdogTickS = 125e-6;

/// dhdGetSystemType's answers MHD knows.
enum SystemType : int {
  kOmega3 = 33, kOmega33 = 34, kOmega331 = 35, kOmega33Left = 36, kOmega331Left = 37, kFalcon = 60, kDelta3 = 63,
  kDelta6 = 64, kSigma331 = 104, kSigma331Left = 105, kSigma33p = 106, kSigma33pLeft = 107
};

/// dhdErrorGetLast's answers the plugin advises on (the SDK's dhd_errors, by value).
enum Error : int {
  kErrorCom = 2, kErrorNoDriverFound = 4, kErrorNoDeviceFound = 5, kErrorNotAvailable = 6, kErrorTimeout = 7,
  kErrorDeviceNotReady = 12, kErrorDeviceInUse = 20
};

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

using DhdRuntime = mhd::vendor::Runtime<DhdCalls>;

/// libdhd (`library`: a name the loader finds, or a path) with every call the plugin
/// makes. Throws std::runtime_error naming the library, what the loader said and how to
/// install the SDK.
std::unique_ptr<DhdRuntime> load_dhd(const std::string& library);

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
