// A device for the haptic server's fault tests: holds its joint angles at a fixed pose in
// the workspace, then fails as fault_injection.h configures.
#include "fault_injection.h"

#include <limits>
#include <new>

namespace {

struct Device {
  const mhd_host* host = nullptr;
  fault_injection::Config config;
};

Device* of(mhd_plugin_instance* self) { return reinterpret_cast<Device*>(self); }

mhd_plugin_instance* open_device(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  auto* d = new (std::nothrow) Device;
  if (d == nullptr) return nullptr;
  d->host = host;
  if (!fault_injection::parse(d->config, params, count, err)) {
    delete d;
    return nullptr;
  }
  return reinterpret_cast<mhd_plugin_instance*>(d);
}
mhd_status ok(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }
void close_device(mhd_plugin_instance* self) {
  fault_injection::write_log(of(self)->config);
  delete of(self);
}
mhd_status limits(mhd_plugin_instance*, mhd_device_limits* out, mhd_error*) {
  out->max_force_N = 8.5;
  for (double& t : out->max_joint_torque_Nm) t = 3.0;
  return MHD_OK;
}
mhd_status read(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err) {
  Device& d = *of(self);
  bool nan = false;
  const mhd_status s = fault_injection::next_read(d.config, nan, err);
  if (s != MHD_OK) return s;
  *out = {};
  out->timestamp_s = d.host->now_s(d.host->clock_context);
  // The PHANToM near the middle of its workspace.
  out->joint_angles_rad[0] = 0.0;
  out->joint_angles_rad[1] = 0.3;
  out->joint_angles_rad[2] = 0.2;
  if (nan) out->joint_angles_rad[1] = std::numeric_limits<double>::quiet_NaN();
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
    mhd_plugin_api a{};
    a.abi_version = MHD_PLUGIN_ABI_VERSION;
    a.struct_size = sizeof(mhd_plugin_api);
    a.kind = MHD_KIND_DEVICE;
    a.name = "fault_device";
    a.version = "1.0.0";
    a.description = "test device that fails on cue";
    a.open = open_device;
    a.start = ok;
    a.stop = ok;
    a.close = close_device;
    a.device_limits = limits;
    a.device_read = read;
    a.device_write = write;
    return a;
  }();
  return &api;
}
