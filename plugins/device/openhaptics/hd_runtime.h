#pragma once
// libHD loaded at run time: the HDAPI calls the plugin makes, found with dlsym. A missing
// library or symbol is one error line that names the library and how to install it.

#include "hd_types.h"
#include "vendor_library.h"

#include <memory>
#include <string>

namespace mhd_openhaptics {

struct HdCalls {
  HHD (*hdInitDevice)(const char* config_name);
  void (*hdDisableDevice)(HHD device);
  void (*hdMakeCurrentDevice)(HHD device);
  HDErrorInfo (*hdGetError)();
  const char* (*hdGetErrorString)(HDerror code);
  void (*hdBeginFrame)(HHD device);
  void (*hdEndFrame)(HHD device);
  void (*hdEnable)(HDenum capability);
  void (*hdDisable)(HDenum capability);
  void (*hdGetDoublev)(HDenum parameter, double* values);
  void (*hdGetIntegerv)(HDenum parameter, int* values);
  const char* (*hdGetString)(HDenum parameter);
  void (*hdSetDoublev)(HDenum parameter, const double* values);
  int (*hdCheckCalibration)();
  void (*hdUpdateCalibration)(HDenum style);
  void (*hdStartScheduler)();
  void (*hdStopScheduler)();
  HDSchedulerHandle (*hdScheduleAsynchronous)(HDSchedulerCallback callback, void* user_data, unsigned short priority);
  void (*hdScheduleSynchronous)(HDSchedulerCallback callback, void* user_data, unsigned short priority);
  void (*hdUnschedule)(HDSchedulerHandle handle);
};

using HdRuntime = mhd::vendor::Runtime<HdCalls>;

/// libHD (`library`: a name the loader finds, or a path) with every call the plugin makes.
/// Throws std::runtime_error naming the library, what the loader said and how to install
/// the runtime.
std::unique_ptr<HdRuntime> load_hd(const std::string& library);

/// "HD_COMM_ERROR", or "HD error 0x1234" for a code HDAPI does not document.
std::string error_name(HDerror code);

/// What the error means for the user and what to do, in a few words.
const char* error_advice(HDerror code) noexcept;

/// "HD_COMM_ERROR (0x0302, device code 7): <vendor text>; <advice>".
std::string describe(const HdCalls& hd, const HDErrorInfo& error);

}  // namespace mhd_openhaptics
