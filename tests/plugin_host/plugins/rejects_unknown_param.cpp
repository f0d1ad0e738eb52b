// Declares no parameters: the host refuses any before open(), and open() would too.
#include "test_device.h"

namespace {
mhd_plugin_instance* open_without_params(const mhd_host* host, const mhd_param* params, size_t count,
                                         mhd_error* err) {
  if (count > 0) {
    test_device::fail_naming(err, "unknown parameter", params[0].name);
    return nullptr;
  }
  return test_device::open(host, params, count, err);
}
}  // namespace

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = test_device::make_api();
    a.open = open_without_params;
    a.params = nullptr;
    a.param_count = 0;
    return a;
  }();
  return &api;
}
