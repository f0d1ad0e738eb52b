#include "isd_runtime.h"

#include <array>

namespace mhd_intersense {
namespace {

constexpr const char* kInstallHint =
    "install the InterSense SDK for Linux (libisense.so, InterSense/Thales), or set the 'library' parameter to "
    "libisense.so's path (docs/hardware.md)";

}  // namespace

std::unique_ptr<IsdRuntime> load_isense(const std::string& library) {
  return std::make_unique<IsdRuntime>(library, "the InterSense SDK", kInstallHint,
                                      [](const mhd::vendor::Binder& bind, IsdCalls& calls) {
                                        bind("ISD_OpenTracker", calls.ISD_OpenTracker);
                                        bind("ISD_CloseTracker", calls.ISD_CloseTracker);
                                        bind("ISD_GetCommInfo", calls.ISD_GetCommInfo);
                                        bind("ISD_GetStationConfig", calls.ISD_GetStationConfig);
                                        bind("ISD_SetStationConfig", calls.ISD_SetStationConfig);
                                        bind("ISD_GetTrackingData", calls.ISD_GetTrackingData);
                                      });
}

std::string model_name(isd::Dword model) {
  // ISD_SYSTEM_MODEL, in order from ISD_UNKNOWN.
  constexpr std::array<const char*, 11> kModels{"an unknown InterSense model", "IS-300", "IS-600", "IS-900",
                                                "InterTrax", "InterTrax 2", "InterTraxLS", "InterTraxLC",
                                                "InertiaCube2", "InertiaCube2 Pro", "IS-1200"};
  if (model < kModels.size()) return kModels[model];
  return "InterSense model " + std::to_string(model);
}

}  // namespace mhd_intersense
