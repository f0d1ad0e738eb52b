// A plugin from ABI 5, before the link kind: like every v5 plugin's MHD_PLUGIN_ENTRY it
// answers only a host that asks for version 5, with a table that says 5. The ABI 6 host
// must refuse it and say so.
#include "test_device.h"

extern "C" const mhd_plugin_api *mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != 5u) return nullptr;
  return test_device::broken_table([](mhd_plugin_api &a) { a.abi_version = 5u; });
}
