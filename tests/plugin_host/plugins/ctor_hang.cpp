// A device whose library never finishes loading: a static constructor sleeps for good.
// Only ever loaded in a child process (isolated_load.h).
#include "test_device.h"

#include <unistd.h>

namespace {
[[gnu::constructor]] void hang_on_load() {
  for (;;) ::pause();
}
}  // namespace

MHD_PLUGIN_ENTRY(test_device::Device, {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                                        .description = "hangs while it loads"})
