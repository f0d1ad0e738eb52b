// A plugin from ABI 3, when mhd_host still carried the simulated world: like every v3
// plugin's MHD_PLUGIN_ENTRY it answers only a host that asks for version 3, with a table
// that says 3. (Version 4 changed only mhd_host, which a host never hands to a plugin it
// refuses, so the v3 table is this header's table with abi_version 3.) The ABI 4 host
// must refuse it and say so.
#include "test_device.h"

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != 3u) return nullptr;
  return test_device::broken_table([](mhd_plugin_api& a) { a.abi_version = 3u; });
}
