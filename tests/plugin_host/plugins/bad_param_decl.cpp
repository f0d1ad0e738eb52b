// Declares a parameter whose own default breaks its range: the host refuses the table.
#include "test_device.h"

namespace {
const mhd_param_decl kBadParams[] = {
    {"rate_hz", MHD_PARAM_NUMBER, "Hz", MHD_PARAM_HAS_MIN | MHD_PARAM_MIN_EXCLUSIVE, 0.0, 0.0, nullptr, "0",
     "samples per second"},
};
}  // namespace

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = test_device::make_api();
    a.params = kBadParams;
    a.param_count = 1;
    return a;
  }();
  return &api;
}
