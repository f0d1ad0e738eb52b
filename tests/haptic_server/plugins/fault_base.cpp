// A base for the haptic server's fault tests: stands still at the origin and records the
// commands it gets, then fails as fault_injection.h configures.
#include "fault_injection.h"

#include <limits>

namespace {

using fault_injection::of;

mhd_status read(mhd_plugin_instance* self, mhd_base_state* out, mhd_error* err) {
  fault_injection::Instance& b = *of(self);
  bool nan = false;
  const mhd_status s = fault_injection::next_read(b.config, nan, err);
  if (s != MHD_OK) return s;
  *out = {};
  out->timestamp_s = b.host->now_s(b.host->clock_context);
  if (nan) out->x_m = std::numeric_limits<double>::quiet_NaN();
  return MHD_OK;
}

mhd_status write(mhd_plugin_instance* self, const mhd_base_command* c, mhd_error*) {
  fault_injection::record(of(self)->config, c->vx_mps, c->vz_mps, c->omega_radps);
  return MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = fault_injection::base_table(MHD_KIND_BASE, "fault_base");
    a.base_read = read;
    a.base_write = write;
    return a;
  }();
  return &api;
}
