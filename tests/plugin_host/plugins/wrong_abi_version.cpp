// Claims the ABI version after this host's.
#include "test_device.h"

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = test_device::make_api();
    a.abi_version = MHD_PLUGIN_ABI_VERSION + 1;
    return a;
  }();
  return &api;
}
