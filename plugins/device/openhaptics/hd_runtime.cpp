#include "hd_runtime.h"

#include "vendor_library.h"

#include <array>
#include <cstdio>

namespace mhd_openhaptics {
namespace {

constexpr const char* kInstallHint =
    "install OpenHaptics for Linux and the device driver from 3D Systems, or name the library with "
    "<param name=\"library\" value=\"/path/to/libHD.so\"/> (docs/hardware.md)";

struct NamedError {
  HDerror code;
  const char* name;
  const char* advice;
};

constexpr std::array kErrors{
    NamedError{hd::kInvalidEnum, "HD_INVALID_ENUM", "the driver does not know a parameter MHD asked for"},
    NamedError{hd::kInvalidValue, "HD_INVALID_VALUE", "the driver refused a value"},
    NamedError{hd::kInvalidOperation, "HD_INVALID_OPERATION", "the driver refused the call in this state"},
    NamedError{hd::kInvalidInputType, "HD_INVALID_INPUT_TYPE", "the driver refused a value's type"},
    NamedError{hd::kBadHandle, "HD_BAD_HANDLE", "the device handle is not valid"},
    NamedError{hd::kWarmMotors, "HD_WARM_MOTORS", "the motors are too warm: let the device cool down"},
    NamedError{hd::kExceededMaxForce, "HD_EXCEEDED_MAX_FORCE", "a force above the device's limit was refused"},
    NamedError{hd::kExceededMaxForceImpulse, "HD_EXCEEDED_MAX_FORCE_IMPULSE",
               "the force changed faster than the device allows"},
    NamedError{hd::kExceededMaxVelocity, "HD_EXCEEDED_MAX_VELOCITY",
               "the tool moved faster than the device's safety limit"},
    NamedError{hd::kForceError, "HD_FORCE_ERROR", "the device could not render the force"},
    NamedError{hd::kDeviceFault, "HD_DEVICE_FAULT", "the device reported a fault: check its status light"},
    NamedError{hd::kDeviceAlreadyInitiated, "HD_DEVICE_ALREADY_INITIATED",
               "another program holds the device: close it"},
    NamedError{hd::kCommError, "HD_COMM_ERROR",
               "communication with the device failed: is it plugged in and powered, and set up with Touch_Setup?"},
    NamedError{hd::kCommConfigError, "HD_COMM_CONFIG_ERROR", "the device's port is not configured: run Touch_Setup"},
    NamedError{hd::kTimerError, "HD_TIMER_ERROR", "the driver's servo timer failed"},
    NamedError{hd::kIllegalBegin, "HD_ILLEGAL_BEGIN", "a frame began inside a frame"},
    NamedError{hd::kIllegalEnd, "HD_ILLEGAL_END", "a frame ended outside a frame"},
    NamedError{hd::kFrameError, "HD_FRAME_ERROR", "the servo frame failed"},
    NamedError{hd::kInvalidPriority, "HD_INVALID_PRIORITY", "the scheduler refused the priority"},
    NamedError{hd::kSchedulerFull, "HD_SCHEDULER_FULL", "the scheduler has no room for the servo callback"},
    NamedError{hd::kInvalidLicense, "HD_INVALID_LICENSE", "the OpenHaptics licence is not valid"},
};

}  // namespace

HdRuntime::HdRuntime(const std::string& library) {
  handle_ = mhd::vendor::open_library(library, "the OpenHaptics runtime", kInstallHint);
  try {
    const mhd::vendor::Binder bind{handle_, library, "the OpenHaptics runtime", kInstallHint};
    bind("hdInitDevice", calls_.hdInitDevice);
    bind("hdDisableDevice", calls_.hdDisableDevice);
    bind("hdMakeCurrentDevice", calls_.hdMakeCurrentDevice);
    bind("hdGetError", calls_.hdGetError);
    bind("hdGetErrorString", calls_.hdGetErrorString);
    bind("hdBeginFrame", calls_.hdBeginFrame);
    bind("hdEndFrame", calls_.hdEndFrame);
    bind("hdEnable", calls_.hdEnable);
    bind("hdDisable", calls_.hdDisable);
    bind("hdGetDoublev", calls_.hdGetDoublev);
    bind("hdGetIntegerv", calls_.hdGetIntegerv);
    bind("hdGetString", calls_.hdGetString);
    bind("hdSetDoublev", calls_.hdSetDoublev);
    bind("hdCheckCalibration", calls_.hdCheckCalibration);
    bind("hdUpdateCalibration", calls_.hdUpdateCalibration);
    bind("hdStartScheduler", calls_.hdStartScheduler);
    bind("hdStopScheduler", calls_.hdStopScheduler);
    bind("hdScheduleAsynchronous", calls_.hdScheduleAsynchronous);
    bind("hdScheduleSynchronous", calls_.hdScheduleSynchronous);
    bind("hdUnschedule", calls_.hdUnschedule);
  } catch (...) {
    mhd::vendor::close_library(handle_);
    throw;
  }
}

HdRuntime::~HdRuntime() { mhd::vendor::close_library(handle_); }

std::string error_name(HDerror code) {
  for (const NamedError& e : kErrors) {
    if (e.code == code) return e.name;
  }
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "HD error 0x%04x", code);
  return text.data();
}

const char* error_advice(HDerror code) noexcept {
  for (const NamedError& e : kErrors) {
    if (e.code == code) return e.advice;
  }
  return "see the OpenHaptics reference";
}

std::string describe(const HdCalls& hd, const HDErrorInfo& error) {
  std::array<char, 64> codes{};
  std::snprintf(codes.data(), codes.size(), " (0x%04x, device code %d)", error.errorCode, error.internalErrorCode);
  const char* vendor = hd.hdGetErrorString(error.errorCode);
  std::string out = error_name(error.errorCode) + codes.data();
  if (vendor != nullptr && *vendor != '\0') out += std::string(": ") + vendor;
  return out + "; " + error_advice(error.errorCode);
}

}  // namespace mhd_openhaptics
