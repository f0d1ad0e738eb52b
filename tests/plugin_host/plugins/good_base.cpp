// A base that remembers the last velocity command and reports it in base_read.
#include <mhd/plugin_sdk.hpp>

namespace {

struct Base {
  explicit Base(const mhd::sdk::Params&) {}
  void base_read(mhd_base_state& out) const {
    out = mhd_base_state{};
    out.timestamp_s = last.timestamp_s;
    out.vx_mps = last.vx_mps;
    out.vz_mps = last.vz_mps;
    out.omega_radps = last.omega_radps;
  }
  void base_write(const mhd_base_command& command) { last = command; }

  mhd_base_command last{};
};

}  // namespace

MHD_PLUGIN_ENTRY(Base, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = nullptr, .description = nullptr})
