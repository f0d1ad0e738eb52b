// open() always fails and says why.
#include "test_device.h"

namespace {
mhd_plugin_instance* open_fails(const mhd_host*, const mhd_param*, size_t, mhd_error* err) {
  test_device::fail(err, "no device on /dev/ttyUSB0");
  return nullptr;
}
}  // namespace

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = test_device::make_api();
    a.open = open_fails;
    return a;
  }();
  return &api;
}
