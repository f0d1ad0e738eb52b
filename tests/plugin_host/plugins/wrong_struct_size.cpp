// Built with a larger table than this host's (a newer header with one more pointer).
#include "test_device.h"

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = test_device::make_api();
    a.struct_size = static_cast<uint32_t>(sizeof(mhd_plugin_api) + sizeof(void*));
    return a;
  }();
  return &api;
}
