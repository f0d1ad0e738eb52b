// Built with a larger table than this host's (a newer header with one more pointer).
#include "test_device.h"

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  return test_device::broken_table(
      [](mhd_plugin_api& a) { a.struct_size = static_cast<uint32_t>(sizeof(mhd_plugin_api) + sizeof(void*)); });
}
