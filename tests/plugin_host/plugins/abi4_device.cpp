// A plugin from ABI 4, before the base had a lift: like every v4 plugin's
// MHD_PLUGIN_ENTRY it answers only a host that asks for version 4, with a table that says
// 4. (Version 5 grew only the base's state and command, so the v4 table is this header's
// table with abi_version 4.) The ABI 5 host must refuse it and say so.
#include "test_device.h"

extern "C" const mhd_plugin_api *mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != 4u) return nullptr;
  return test_device::broken_table([](mhd_plugin_api &a) { a.abi_version = 4u; });
}
