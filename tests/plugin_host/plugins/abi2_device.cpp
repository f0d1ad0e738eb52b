// A device plugin as it was written for plugin ABI 2 (joint angles in, joint torques out),
// built against the frozen v2 header (tests/plugin_host/abi2): like every v2 plugin it
// answers only a host that asks for version 2. A later host must refuse it and say so.
#include <mhd/plugin_abi.h>

static_assert(MHD_PLUGIN_ABI_VERSION == 2u, "abi2_device must be built against the frozen ABI 2 header");

namespace {

int g_instance = 0;

mhd_plugin_instance* open(const mhd_host*, const mhd_param*, size_t, mhd_error*) {
  return reinterpret_cast<mhd_plugin_instance*>(&g_instance);
}
mhd_status ok(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }
void close(mhd_plugin_instance*) {}
mhd_status limits(mhd_plugin_instance*, mhd_device_limits* out, mhd_error*) {
  *out = mhd_device_limits{8.5, {1.0, 1.0, 1.0}};
  return MHD_OK;
}
mhd_status read(mhd_plugin_instance*, mhd_device_state* out, mhd_error*) {
  *out = mhd_device_state{};
  return MHD_OK;
}
mhd_status write(mhd_plugin_instance*, const mhd_device_command*, mhd_error*) { return MHD_OK; }

mhd_plugin_api make_api() {
  mhd_plugin_api api{};
  api.abi_version = MHD_PLUGIN_ABI_VERSION;
  api.struct_size = sizeof(mhd_plugin_api);
  api.kind = MHD_KIND_DEVICE;
  api.name = MHD_PLUGIN_NAME;
  api.version = "2.0.0";
  api.description = "an ABI 2 device";
  api.open = open;
  api.start = ok;
  api.stop = ok;
  api.close = close;
  api.device_limits = limits;
  api.device_read = read;
  api.device_write = write;
  return api;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  static const mhd_plugin_api api = make_api();
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &api : nullptr;
}
