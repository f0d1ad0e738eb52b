// A device whose library ends the process while it loads: a static constructor calls
// exit(0). Only ever loaded in a child process (isolated_load.h).
#include "test_device.h"

#include <cstdlib>

namespace {
[[gnu::constructor]] void exit_on_load() { std::exit(0); }
}  // namespace

MHD_PLUGIN_ENTRY(test_device::Device, {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                                        .description = "exits while it loads"})
