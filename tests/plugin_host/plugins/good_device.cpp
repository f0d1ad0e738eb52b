// A device that returns fixed data (test_device.h). It also exports its call log, so
// tests can see which lifecycle calls reached the plugin.
#include "test_device.h"

MHD_PLUGIN_ENTRY(test_device::Device, {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.2.3",
                                        .description = "test device"})

extern "C" MHD_PLUGIN_EXPORT const char* mhd_test_call_log();
extern "C" MHD_PLUGIN_EXPORT void mhd_test_clear_call_log();
const char* mhd_test_call_log() { return test_device::call_log; }
void mhd_test_clear_call_log() { test_device::call_log[0] = '\0'; }
