// A device that returns fixed data (test_device.h). It also exports its call log, so
// tests can see which lifecycle calls reached the plugin.
#include "test_device.h"

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = test_device::make_api();
  return &api;
}

extern "C" MHD_PLUGIN_EXPORT const char* mhd_test_call_log();
extern "C" MHD_PLUGIN_EXPORT void mhd_test_clear_call_log();

const char* mhd_test_call_log() { return test_device::call_log; }
void mhd_test_clear_call_log() { test_device::call_log[0] = '\0'; }
