// A device without device_read.
#include "test_device.h"

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = test_device::make_api();
    a.device_read = nullptr;
    return a;
  }();
  return &api;
}
