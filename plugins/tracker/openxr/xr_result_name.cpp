#include "xr_result_name.h"

#include <openxr/openxr_reflection.h>

namespace mhd::openxr {

std::string result_name(XrResult result) {
  // The registry's own list (openxr_reflection.h), so the names track the headers.
  switch (result) {
#define MHD_XR_RESULT_CASE(name, value) \
  case name:                            \
    return #name;
    XR_LIST_ENUM_XrResult(MHD_XR_RESULT_CASE)
#undef MHD_XR_RESULT_CASE
    default:
      return "XrResult " + std::to_string(static_cast<int>(result));
  }
}

bool means_no_runtime(XrResult result) noexcept {
  return result == XR_ERROR_RUNTIME_UNAVAILABLE || result == XR_ERROR_RUNTIME_FAILURE;
}

}  // namespace mhd::openxr
