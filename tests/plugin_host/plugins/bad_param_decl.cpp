// Declares a parameter whose own default breaks its range: the host refuses the table.
#include "test_device.h"

namespace {

struct BadDeclaration : test_device::Device {
  static constexpr std::array kParams{
      mhd::sdk::number("rate_hz", "Hz", "0", "samples per second", mhd::sdk::positive()),
  };
  BadDeclaration(const mhd_host& host, const mhd::sdk::Params&) : Device(host, test_device::Settings{}) {}
};

}  // namespace

MHD_PLUGIN_ENTRY(BadDeclaration, {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.2.3",
                                  .description = "test device with a bad declaration"})
