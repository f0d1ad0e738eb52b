// A device for the haptic server's fault tests: holds its tool at a fixed point in the
// workspace, then fails as fault_injection.h configures.
#include "fault_injection.h"

#include "phantom_like_device_info.h"

namespace {

class FaultDevice {
 public:
  static constexpr auto kParams = fault_injection::kParams;
  FaultDevice(const mhd_host& host, const mhd::sdk::Params& params) : hardware_(host, params) {}

  void device_info(mhd_device_info& out) { out = test_plugins::phantom_like_device_info(); }
  mhd_status device_read(mhd_device_state& out) {
    bool absurd = false;
    if (const mhd_status s = hardware_.next_read(absurd); s != MHD_OK) return s;
    out = {};
    out.timestamp_s = hardware_.now_s();
    for (std::size_t i = 0; i < 3; ++i) out.p_D_tool_m[i] = test_plugins::kPhantomMidTool_D_m[i];
    out.q_D_tool_wxyz[0] = 1.0;
    if (absurd) out.p_D_tool_m[1] = hardware_.absurd();
    return MHD_OK;
  }
  void device_write(const mhd_device_command& c) { hardware_.record(c.force_D_N[0], c.force_D_N[1], c.force_D_N[2]); }

 private:
  fault_injection::FaultyHardware hardware_;
};

}  // namespace

MHD_PLUGIN_ENTRY(FaultDevice, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                               .description = "test device that fails on cue"})
