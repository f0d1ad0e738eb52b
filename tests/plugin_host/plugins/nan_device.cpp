// device_read returns NaN in p_D_tool_m[1].
#include "test_device.h"

#include <limits>

namespace {
mhd_status read_nan(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err) {
  const mhd_status status = test_device::read(self, out, err);
  out->p_D_tool_m[1] = std::numeric_limits<double>::quiet_NaN();
  return status;
}
}  // namespace

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = test_device::make_api();
    a.device_read = read_nan;
    return a;
  }();
  return &api;
}
