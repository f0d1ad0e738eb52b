// device_read returns NaN in p_D_tool_m[1].
#include "test_device.h"

#include <limits>

namespace {

struct NanDevice : test_device::Device {
  using Device::Device;
  mhd_status device_read(mhd_device_state& out) {
    const mhd_status status = Device::device_read(out);
    out.p_D_tool_m[1] = std::numeric_limits<double>::quiet_NaN();
    return status;
  }
};

}  // namespace

MHD_PLUGIN_ENTRY(NanDevice, {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.2.3",
                             .description = "test device that reads NaN"})
