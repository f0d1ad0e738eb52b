// A device without device_read.
#include "test_device.h"

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  return test_device::broken_table([](mhd_plugin_api& a) { a.device_read = nullptr; });
}
