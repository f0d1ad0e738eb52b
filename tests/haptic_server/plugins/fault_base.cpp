// A base for the haptic server's fault tests: stands still at the origin and records the
// commands it gets, then fails as fault_injection.h configures.
#include "fault_injection.h"

#include <limits>
#include <new>

namespace {

struct Base {
  const mhd_host* host = nullptr;
  fault_injection::Config config;
};

Base* of(mhd_plugin_instance* self) { return reinterpret_cast<Base*>(self); }

mhd_plugin_instance* open_base(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  auto* b = new (std::nothrow) Base;
  if (b == nullptr) return nullptr;
  b->host = host;
  if (!fault_injection::parse(b->config, params, count, err)) {
    delete b;
    return nullptr;
  }
  return reinterpret_cast<mhd_plugin_instance*>(b);
}
mhd_status ok(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }
void close_base(mhd_plugin_instance* self) {
  fault_injection::write_log(of(self)->config);
  delete of(self);
}
mhd_status read(mhd_plugin_instance* self, mhd_base_state* out, mhd_error* err) {
  Base& b = *of(self);
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
    mhd_plugin_api a{};
    a.abi_version = MHD_PLUGIN_ABI_VERSION;
    a.struct_size = sizeof(mhd_plugin_api);
    a.kind = MHD_KIND_BASE;
    a.name = "fault_base";
    a.version = "1.0.0";
    a.description = "test base that fails on cue";
    a.open = open_base;
    a.start = ok;
    a.stop = ok;
    a.close = close_base;
    a.base_read = read;
    a.base_write = write;
    return a;
  }();
  return &api;
}
