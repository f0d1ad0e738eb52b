// A device for the haptic server's fault tests: holds its tool at a fixed point in the
// workspace, then fails as fault_injection.h configures.
#include "fault_injection.h"

#include <limits>

namespace {

using fault_injection::of;

mhd_status read(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err) {
  fault_injection::Instance& d = *of(self);
  bool nan = false;
  const mhd_status s = fault_injection::next_read(d.config, nan, err);
  if (s != MHD_OK) return s;
  *out = {};
  out->timestamp_s = d.host->now_s(d.host->clock_context);
  // A PHANToM near the middle of its workspace: the tool at joint angles (0, 0.3, 0.2) rad.
  out->p_D_tool_m[0] = 0.0;
  out->p_D_tool_m[1] = 0.06610330791925151;
  out->p_D_tool_m[2] = 0.032271919564375806;
  out->q_D_tool_wxyz[0] = 1.0;
  if (nan) out->p_D_tool_m[1] = fault_injection::absurd(d.config);
  return MHD_OK;
}

mhd_status write(mhd_plugin_instance* self, const mhd_device_command* c, mhd_error*) {
  fault_injection::record(of(self)->config, c->force_D_N[0], c->force_D_N[1], c->force_D_N[2]);
  return MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = fault_injection::base_table(MHD_KIND_DEVICE, "fault_device");
    a.device_info = fault_injection::phantom_like_info;
    a.device_read = read;
    a.device_write = write;
    return a;
  }();
  return &api;
}
