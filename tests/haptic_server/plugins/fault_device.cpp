// A device for the haptic server's fault tests: holds its joint angles at a fixed pose in
// the workspace, then fails as fault_injection.h configures.
#include "fault_injection.h"

#include <limits>

namespace {

using fault_injection::of;

mhd_status limits(mhd_plugin_instance*, mhd_device_limits* out, mhd_error*) {
  out->max_force_N = 8.5;
  for (double& t : out->max_joint_torque_Nm) t = 3.0;
  return MHD_OK;
}

mhd_status read(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err) {
  fault_injection::Instance& d = *of(self);
  bool nan = false;
  const mhd_status s = fault_injection::next_read(d.config, nan, err);
  if (s != MHD_OK) return s;
  *out = {};
  out->timestamp_s = d.host->now_s(d.host->clock_context);
  // The PHANToM near the middle of its workspace.
  out->joint_angles_rad[0] = 0.0;
  out->joint_angles_rad[1] = 0.3;
  out->joint_angles_rad[2] = 0.2;
  if (nan) out->joint_angles_rad[1] = fault_injection::absurd(d.config);
  return MHD_OK;
}

mhd_status write(mhd_plugin_instance* self, const mhd_device_command* c, mhd_error*) {
  fault_injection::record(of(self)->config, c->joint_torques_Nm[0], c->joint_torques_Nm[1], c->joint_torques_Nm[2]);
  return MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = fault_injection::base_table(MHD_KIND_DEVICE, "fault_device");
    a.device_limits = limits;
    a.device_read = read;
    a.device_write = write;
    return a;
  }();
  return &api;
}
