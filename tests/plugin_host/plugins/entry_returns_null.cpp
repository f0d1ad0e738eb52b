// Refuses every host.
#include <mhd/plugin_abi.h>

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) { return nullptr; }
