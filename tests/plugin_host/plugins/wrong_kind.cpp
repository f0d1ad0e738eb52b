// Kind 99, written as raw bytes: the enum cannot hold it, but a C plugin could send it.
#include "test_device.h"

#include <cstring>

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  return test_device::broken_table([](mhd_plugin_api& a) {
    const uint32_t kind = 99;
    static_assert(sizeof(kind) == sizeof(a.kind));
    std::memcpy(&a.kind, &kind, sizeof(kind));
  });
}
