// A base for the haptic server's fault tests: stands still at the origin and records the
// commands it gets, then fails as fault_injection.h configures.
#include "fault_injection.h"

namespace {

class FaultBase {
 public:
  static constexpr auto kParams = fault_injection::kParams;
  FaultBase(const mhd_host& host, const mhd::sdk::Params& params) : hardware_(host, params) {}

  mhd_status base_read(mhd_base_state& out) {
    bool absurd = false;
    if (const mhd_status s = hardware_.next_read(absurd); s != MHD_OK) return s;
    out = {};
    out.timestamp_s = hardware_.now_s();
    if (absurd) out.x_m = hardware_.absurd();
    return MHD_OK;
  }
  void base_write(const mhd_base_command& c) { hardware_.record(c.vx_mps, c.vz_mps, c.omega_radps); }

 private:
  fault_injection::FaultyHardware hardware_;
};

}  // namespace

MHD_PLUGIN_ENTRY(FaultBase, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                             .description = "test base that fails on cue"})
