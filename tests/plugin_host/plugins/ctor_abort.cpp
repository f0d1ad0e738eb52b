// A device whose library crashes while it loads: a static constructor aborts. Only ever
// loaded in a child process (isolated_load.h).
#include "test_device.h"

#include <cstdlib>

namespace {
[[gnu::constructor]] void abort_on_load() { std::abort(); }
}  // namespace

MHD_PLUGIN_ENTRY(test_device::Device, {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                                        .description = "aborts while it loads"})
