#include "hd_runtime.h"

#include "vendor_library.h"

#include <array>
#include <cstdio>

namespace mhd_openhaptics {
namespace {

constexpr const char* kInstallHint =
    "install OpenHaptics for Linux and the device driver (3D Systems), or set the 'library' parameter to "
    "libHD.so's path (docs/hardware.md)";

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

std::unique_ptr<HdRuntime> load_hd(const std::string& library) {
  return std::make_unique<HdRuntime>(library, "the OpenHaptics runtime", kInstallHint,
                                     [](const mhd::vendor::Binder& bind, HdCalls& calls) {
                                       bind("hdInitDevice", calls.hdInitDevice);
                                       bind("hdDisableDevice", calls.hdDisableDevice);
                                       bind("hdMakeCurrentDevice", calls.hdMakeCurrentDevice);
                                       bind("hdGetError", calls.hdGetError);
                                       bind("hdGetErrorString", calls.hdGetErrorString);
                                       bind("hdBeginFrame", calls.hdBeginFrame);
                                       bind("hdEndFrame", calls.hdEndFrame);
                                       bind("hdEnable", calls.hdEnable);
                                       bind("hdDisable", calls.hdDisable);
                                       bind("hdGetDoublev", calls.hdGetDoublev);
                                       bind("hdGetIntegerv", calls.hdGetIntegerv);
                                       bind("hdGetString", calls.hdGetString);
                                       bind("hdSetDoublev", calls.hdSetDoublev);
                                       bind("hdCheckCalibration", calls.hdCheckCalibration);
                                       bind("hdUpdateCalibration", calls.hdUpdateCalibration);
                                       bind("hdStartScheduler", calls.hdStartScheduler);
                                       bind("hdStopScheduler", calls.hdStopScheduler);
                                       bind("hdScheduleAsynchronous", calls.hdScheduleAsynchronous);
                                       bind("hdScheduleSynchronous", calls.hdScheduleSynchronous);
                                       bind("hdUnschedule", calls.hdUnschedule);
                                     });
}

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
  std::array<char, 48> codes{};
  std::snprintf(codes.data(), codes.size(), "0x%04x, device code %d", error.errorCode, error.internalErrorCode);
  return mhd::vendor::describe_error(error_name(error.errorCode), codes.data(), hd.hdGetErrorString(error.errorCode),
                                     error_advice(error.errorCode));
}

}  // namespace mhd_openhaptics
