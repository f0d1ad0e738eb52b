#pragma once
// libisense loaded at run time: the InterSense SDK calls the plugin makes, found with
// dlsym. A missing library or call is one error line that names the library and how to
// install it. The test fake of libisense (tests/hardware/fakes/fake_isense.cpp) implements
// the same calls.

#include "isd_types.h"
#include "vendor_library.h"

#include <memory>
#include <string>

namespace mhd_intersense {

struct IsdCalls {
  isd::Handle (*ISD_OpenTracker)(void* parent_window, isd::Dword comm_port, isd::Bool info_screen, isd::Bool verbose);
  isd::Bool (*ISD_CloseTracker)(isd::Handle handle);
  isd::Bool (*ISD_GetCommInfo)(isd::Handle handle, isd::TrackerInfo* tracker);
  isd::Bool (*ISD_GetStationConfig)(isd::Handle handle, isd::StationInfo* station, std::uint16_t station_id,
                                    isd::Bool verbose);
  isd::Bool (*ISD_SetStationConfig)(isd::Handle handle, isd::StationInfo* station, std::uint16_t station_id,
                                    isd::Bool verbose);
  isd::Bool (*ISD_GetTrackingData)(isd::Handle handle, isd::TrackingData* data);
};

using IsdRuntime = mhd::vendor::Runtime<IsdCalls>;

/// The library versions whose data layout isd_types.h declares: [min, max).
constexpr float kMinLibVersion = 4.0F;
constexpr float kMaxLibVersion = 5.0F;

/// libisense (`library`: a name the loader finds, or a path) with every call the plugin
/// makes. Throws std::runtime_error naming the library, what the loader said and how to
/// install the runtime.
std::unique_ptr<IsdRuntime> load_isense(const std::string& library);

/// "IS-900", or "InterSense model 7" for a model the plugin does not name.
std::string model_name(isd::Dword model);

}  // namespace mhd_intersense
