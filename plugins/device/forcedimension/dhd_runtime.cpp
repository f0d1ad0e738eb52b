#include "dhd_runtime.h"

#include <array>
#include <cstdio>
#include <stdexcept>

namespace mhd_forcedimension {
namespace {

constexpr const char* kInstallHint =
    "install the Force Dimension SDK for Linux (forcedimension.com), or set the 'library' parameter to "
    "libdhd.so's path (docs/hardware.md)";

// The SDK's documented error codes, in the order of its dhd_errors.
constexpr std::array kErrorNames{
    "DHD_NO_ERROR", "DHD_ERROR", "DHD_ERROR_COM", "DHD_ERROR_DHC_BUSY", "DHD_ERROR_NO_DRIVER_FOUND",
    "DHD_ERROR_NO_DEVICE_FOUND", "DHD_ERROR_NOT_AVAILABLE", "DHD_ERROR_TIMEOUT", "DHD_ERROR_GEOMETRY",
    "DHD_ERROR_EXPERT_MODE_DISABLED", "DHD_ERROR_NOT_IMPLEMENTED", "DHD_ERROR_OUT_OF_MEMORY",
    "DHD_ERROR_DEVICE_NOT_READY", "DHD_ERROR_FILE_NOT_FOUND", "DHD_ERROR_CONFIGURATION", "DHD_ERROR_INVALID_INDEX",
    "DHD_ERROR_DEPRECATED", "DHD_ERROR_NULL_ARGUMENT", "DHD_ERROR_REDUNDANT_FAIL", "DHD_ERROR_NOT_ENABLED",
    "DHD_ERROR_DEVICE_IN_USE", "DHD_ERROR_INVALID"};

const char* advice(int code) noexcept {
  switch (code) {
    case dhd::kErrorCom:
      return "communication with the device failed: is its USB cable in and the controller powered?";
    case dhd::kErrorNoDriverFound:
      return "the device's driver is not installed (see the SDK's README for the udev rules)";
    case dhd::kErrorNoDeviceFound:
      return "no device found: is it plugged in, powered and initialised (the SDK's autoinit)?";
    case dhd::kErrorTimeout:
      return "the device did not answer in time";
    case dhd::kErrorDeviceNotReady:
      return "the device is not ready: calibrate it (the SDK's autocenter or autoinit)";
    case dhd::kErrorDeviceInUse:
      return "another program holds the device: close it";
    case dhd::kErrorNotAvailable:
      return "the device does not offer this";
    default:
      return "see the Force Dimension SDK's reference";
  }
}

// Nominal figures from the manufacturer's data sheets: continuous force, closed-loop
// stiffness, and a box inside the translation workspace.
constexpr DeviceModel kOmega{"omega.x", 12.0, 14500.0, {0.05, 0.07, 0.05}};
constexpr DeviceModel kSigma{"sigma.7", 20.0, 14500.0, {0.06, 0.08, 0.06}};
constexpr DeviceModel kDelta{"delta.x", 20.0, 14500.0, {0.12, 0.18, 0.12}};
constexpr DeviceModel kFalcon{"Novint Falcon", 8.9, 1500.0, {0.05, 0.05, 0.05}};

}  // namespace

std::unique_ptr<DhdRuntime> load_dhd(const std::string& library) {
  return std::make_unique<DhdRuntime>(library, "the Force Dimension SDK", kInstallHint,
                                      [](const mhd::vendor::Binder& bind, DhdCalls& calls) {
                                        bind("dhdOpen", calls.dhdOpen);
                                        bind("dhdOpenSerial", calls.dhdOpenSerial);
                                        bind("dhdClose", calls.dhdClose);
                                        bind("dhdStop", calls.dhdStop);
                                        bind("dhdGetSystemType", calls.dhdGetSystemType);
                                        bind("dhdGetSystemName", calls.dhdGetSystemName);
                                        bind("dhdEnableForce", calls.dhdEnableForce);
                                        bind("dhdSetGravityCompensation", calls.dhdSetGravityCompensation);
                                        bind("dhdSetWatchdog", calls.dhdSetWatchdog);
                                        bind("dhdGetPosition", calls.dhdGetPosition);
                                        bind("dhdGetLinearVelocity", calls.dhdGetLinearVelocity);
                                        bind("dhdGetButtonMask", calls.dhdGetButtonMask);
                                        bind("dhdGetStatus", calls.dhdGetStatus);
                                        bind("dhdSetForce", calls.dhdSetForce);
                                        bind("dhdErrorGetLast", calls.dhdErrorGetLast);
                                        bind("dhdErrorGetStr", calls.dhdErrorGetStr);
                                      });
}

std::string describe_last_error(const DhdCalls& dhd, const char* call) {
  const int code = dhd.dhdErrorGetLast();
  std::string name = "DHD error";
  if (code >= 0 && static_cast<std::size_t>(code) < kErrorNames.size()) name = kErrorNames[static_cast<std::size_t>(code)];
  return mhd::vendor::describe_error(std::string(call) + ": " + name, std::to_string(code), dhd.dhdErrorGetStr(code),
                                     advice(code));
}

const char* force_off_cause(int cause) noexcept {
  switch (cause) {
    case 1:
      return "the force button was pressed";
    case 2:
      return "the tool moved faster than the device's velocity threshold";
    case 3:
      return "its firmware watchdog fired: no force command within command_timeout_s";
    case 4:
      return "software turned them off";
    case 5:
      return "the USB link was lost";
    case 6:
      return "the dead-man switch was released";
    default:
      return "no cause given";
  }
}

const DeviceModel* model_of(int system_type) noexcept {
  switch (system_type) {
    case dhd::kOmega3:
    case dhd::kOmega33:
    case dhd::kOmega33Left:
    case dhd::kOmega331:
    case dhd::kOmega331Left:
      return &kOmega;
    case dhd::kSigma331:
    case dhd::kSigma331Left:
    case dhd::kSigma33p:
    case dhd::kSigma33pLeft:
      return &kSigma;
    case dhd::kDelta3:
    case dhd::kDelta6:
      return &kDelta;
    case dhd::kFalcon:
      return &kFalcon;
    default:
      return nullptr;
  }
}

}  // namespace mhd_forcedimension
