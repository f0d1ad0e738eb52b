#pragma once
// The part of OpenHaptics' HDAPI (3D Systems) the openhaptics plugin calls, declared from
// the toolkit's reference: types, the constants it passes and the error codes it names.
// The toolkit is not a Debian package, so the plugin is built without it and loads
// libHD.so when it opens (hd_runtime.h). Units are HDAPI's: millimetres, mm/s, newtons,
// N/mm. The test fake of libHD (tests/hardware/fake_openhaptics) implements the same calls.

#include <climits>

namespace mhd_openhaptics {

using HHD = unsigned int;
using HDenum = unsigned int;
using HDerror = unsigned int;
using HDCallbackCode = unsigned int;
using HDSchedulerHandle = unsigned long;
using HDSchedulerCallback = HDCallbackCode (*)(void* user_data);

/// Returned by value from hdGetError, as in HDAPI.
struct HDErrorInfo {
  HDerror errorCode;
  int internalErrorCode;
  HHD hHD;
};

namespace hd {

constexpr HHD kInvalidHandle = 0xFFFFFFFFu;
constexpr HDCallbackCode kCallbackDone = 0;
constexpr HDCallbackCode kCallbackContinue = 1;
constexpr unsigned short kMaxSchedulerPriority = USHRT_MAX;

// Error codes.
constexpr HDerror kSuccess = 0x0000;
constexpr HDerror kInvalidEnum = 0x0100;
constexpr HDerror kInvalidValue = 0x0101;
constexpr HDerror kInvalidOperation = 0x0102;
constexpr HDerror kInvalidInputType = 0x0103;
constexpr HDerror kBadHandle = 0x0104;
constexpr HDerror kWarmMotors = 0x0200;
constexpr HDerror kExceededMaxForce = 0x0201;
constexpr HDerror kExceededMaxForceImpulse = 0x0202;
constexpr HDerror kExceededMaxVelocity = 0x0203;
constexpr HDerror kForceError = 0x0204;
constexpr HDerror kDeviceFault = 0x0300;
constexpr HDerror kDeviceAlreadyInitiated = 0x0301;
constexpr HDerror kCommError = 0x0302;
constexpr HDerror kCommConfigError = 0x0303;
constexpr HDerror kTimerError = 0x0304;
constexpr HDerror kIllegalBegin = 0x0400;
constexpr HDerror kIllegalEnd = 0x0401;
constexpr HDerror kFrameError = 0x0402;
constexpr HDerror kInvalidPriority = 0x0500;
constexpr HDerror kSchedulerFull = 0x0501;
constexpr HDerror kInvalidLicense = 0x0600;

// Parameters (hdGet*, hdSet*).
constexpr HDenum kCurrentButtons = 0x2000;
constexpr HDenum kCurrentPosition = 0x2050;  ///< 3 doubles, mm
constexpr HDenum kCurrentVelocity = 0x2051;  ///< 3 doubles, mm/s
constexpr HDenum kCurrentTransform = 0x2052; ///< 16 doubles, column-major, translation in mm
constexpr HDenum kCurrentJointAngles = 0x2100;   ///< 3 doubles, rad: the arm's base, shoulder and elbow
constexpr HDenum kCurrentGimbalAngles = 0x2150;  ///< 3 doubles, rad: the stylus gimbal's
constexpr HDenum kDeviceModelType = 0x2501;
constexpr HDenum kDeviceSerialNumber = 0x2504;
constexpr HDenum kUsableWorkspaceDimensions = 0x2551;  ///< min x y z, max x y z, mm
constexpr HDenum kInputDof = 0x2553;
constexpr HDenum kOutputDof = 0x2554;
constexpr HDenum kCalibrationStyle = 0x2555;
constexpr HDenum kNominalMaxStiffness = 0x2602;  ///< N/mm
constexpr HDenum kNominalMaxForce = 0x2603;      ///< N
constexpr HDenum kMotorTemperature = 0x2605;     ///< per motor, 0 cold .. 1 at the limit
constexpr HDenum kCurrentForce = 0x2700;         ///< 3 doubles, N

// Capabilities (hdEnable, hdDisable).
constexpr HDenum kForceOutput = 0x4000;

// hdCheckCalibration.
constexpr int kCalibrationOk = 0x5000;
constexpr int kCalibrationNeedsUpdate = 0x5001;
constexpr int kCalibrationNeedsManualInput = 0x5002;

/// HDAPI reports the temperature of up to this many motors.
constexpr int kMaxMotors = 6;

}  // namespace hd
}  // namespace mhd_openhaptics
