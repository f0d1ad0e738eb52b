// libmhd_misnamed.so whose table says it is someone_else.
#include "test_device.h"

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  return test_device::broken_table([](mhd_plugin_api& a) { a.name = "someone_else"; });
}
