// open() always fails and says why.
#include "test_device.h"

namespace {

struct OpenFails : test_device::Device {
  OpenFails(const mhd_host& host, const mhd::sdk::Params& params) : Device(host, params) {
    throw std::runtime_error("no device on /dev/ttyUSB0");
  }
};

}  // namespace

MHD_PLUGIN_ENTRY(OpenFails, {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.2.3",
                             .description = "test device whose open fails"})
