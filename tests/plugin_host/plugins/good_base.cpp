// A base that remembers the last velocity command and reports it in base_read.
#include <mhd/plugin_abi.h>

#include <cstdio>
#include <new>

namespace {

struct Base {
  mhd_base_command last{};
};

Base* base_of(mhd_plugin_instance* self) { return reinterpret_cast<Base*>(self); }

mhd_plugin_instance* base_open(const mhd_host*, const mhd_param* params, size_t count, mhd_error* err) {
  if (count > 0) {
    std::snprintf(err->message, sizeof(err->message), "unknown parameter '%s'", params[0].name);
    return nullptr;
  }
  return reinterpret_cast<mhd_plugin_instance*>(new (std::nothrow) Base);
}

mhd_status base_start(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }
mhd_status base_stop(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }
void base_close(mhd_plugin_instance* self) { delete base_of(self); }

mhd_status base_read(mhd_plugin_instance* self, mhd_base_state* out, mhd_error*) {
  const Base* b = base_of(self);
  *out = mhd_base_state{};
  out->timestamp_s = b->last.timestamp_s;
  out->vx_mps = b->last.vx_mps;
  out->vz_mps = b->last.vz_mps;
  out->omega_radps = b->last.omega_radps;
  return MHD_OK;
}

mhd_status base_write(mhd_plugin_instance* self, const mhd_base_command* command, mhd_error*) {
  base_of(self)->last = *command;
  return MHD_OK;
}

mhd_plugin_api make_api() {
  mhd_plugin_api api{};
  api.abi_version = MHD_PLUGIN_ABI_VERSION;
  api.struct_size = sizeof(mhd_plugin_api);
  api.kind = MHD_PLUGIN_KIND;
  api.name = MHD_PLUGIN_NAME;
  api.open = base_open;
  api.start = base_start;
  api.stop = base_stop;
  api.close = base_close;
  api.base_read = base_read;
  api.base_write = base_write;
  return api;
}

}  // namespace

extern "C" const mhd_plugin_api* mhd_plugin_entry(uint32_t /*host_abi_version*/) {
  static const mhd_plugin_api api = make_api();
  return &api;
}
