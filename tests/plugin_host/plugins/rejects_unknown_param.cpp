// Declares no parameters: the host refuses any before open(), and open() would too.
#include "test_device.h"

namespace {

struct NoParams : test_device::Device {
  static constexpr std::array<mhd_param_decl, 0> kParams{};
  NoParams(const mhd_host& host, const mhd::sdk::Params&) : Device(host, test_device::Settings{}) {}
};

}  // namespace

MHD_PLUGIN_ENTRY(NoParams, {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.2.3",
                            .description = "test device without parameters"})
