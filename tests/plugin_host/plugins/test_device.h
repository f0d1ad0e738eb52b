#pragma once
// A small, valid device plugin that each test plugin starts from and breaks in one way.
// Params (each optional and declared, so the host checks them; any other name is refused):
//   tool_x_m=<double>  p_D_tool_m[0] returned by device_read (default 0.05)
//   max_force_N=<double>  the device_info force limit (default 8.5)
//   read_status=ok|no_data|deactivate|error|bogus  what device_read returns
//   fail=start|stop  that call returns MHD_ERROR
// device_read reports the host clock in timestamp_s, the last written force in
// v_D_tool_mps and the number of reads so far in buttons. Lifecycle calls are appended to
// call_log ("open start stop close "), which good_device exports for the tests.

#include <mhd/plugin_abi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

namespace test_device {

struct Device {
  const mhd_host* host = nullptr;
  double tool_x_m = 0.05;
  double max_force_N = 8.5;
  int read_status = MHD_OK;
  bool fail_start = false;
  bool fail_stop = false;
  double last_force_N[3] = {0.0, 0.0, 0.0};
  unsigned reads = 0;
};

inline char call_log[256] = {};

inline void log_call(const char* call) {
  std::strncat(call_log, call, sizeof(call_log) - std::strlen(call_log) - 1);
  std::strncat(call_log, " ", sizeof(call_log) - std::strlen(call_log) - 1);
}

inline Device* device_of(mhd_plugin_instance* self) { return reinterpret_cast<Device*>(self); }

inline void fail(mhd_error* err, const char* text) { std::snprintf(err->message, sizeof(err->message), "%s", text); }

/// "WHAT 'NAME'", e.g. "unknown parameter 'x'".
inline void fail_naming(mhd_error* err, const char* what, const char* name) {
  std::snprintf(err->message, sizeof(err->message), "%s '%s'", what, name);
}

inline bool parse_param(Device& d, const mhd_param& p, mhd_error* err) {
  if (std::strcmp(p.name, "tool_x_m") == 0) {
    d.tool_x_m = std::strtod(p.value, nullptr);
  } else if (std::strcmp(p.name, "max_force_N") == 0) {
    d.max_force_N = std::strtod(p.value, nullptr);
  } else if (std::strcmp(p.name, "read_status") == 0) {
    if (std::strcmp(p.value, "ok") == 0) d.read_status = MHD_OK;
    else if (std::strcmp(p.value, "no_data") == 0) d.read_status = MHD_NO_DATA;
    else if (std::strcmp(p.value, "deactivate") == 0) d.read_status = MHD_DEACTIVATE;
    else if (std::strcmp(p.value, "error") == 0) d.read_status = MHD_ERROR;
    else if (std::strcmp(p.value, "bogus") == 0) d.read_status = 7;
    else {
      fail_naming(err, "bad read_status", p.value);
      return false;
    }
  } else if (std::strcmp(p.name, "fail") == 0) {
    d.fail_start = std::strcmp(p.value, "start") == 0;
    d.fail_stop = std::strcmp(p.value, "stop") == 0;
  } else {
    fail_naming(err, "unknown parameter", p.name);
    return false;
  }
  return true;
}

inline mhd_plugin_instance* open(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  log_call("open");
  Device d;
  d.host = host;
  for (size_t i = 0; i < count; ++i) {
    if (!parse_param(d, params[i], err)) return nullptr;
  }
  return reinterpret_cast<mhd_plugin_instance*>(new (std::nothrow) Device(d));
}

inline mhd_status start(mhd_plugin_instance* self, mhd_error* err) {
  log_call("start");
  if (!device_of(self)->fail_start) return MHD_OK;
  fail(err, "motors not powered");
  return MHD_ERROR;
}

inline mhd_status stop(mhd_plugin_instance* self, mhd_error* err) {
  log_call("stop");
  if (!device_of(self)->fail_stop) return MHD_OK;
  fail(err, "brake did not engage");
  return MHD_ERROR;
}

inline void close(mhd_plugin_instance* self) {
  log_call("close");
  delete device_of(self);
}

inline mhd_status info(mhd_plugin_instance* self, mhd_device_info* out, mhd_error* /*err*/) {
  const Device* d = device_of(self);
  *out = mhd_device_info{};
  out->max_force_N = d->max_force_N;
  out->max_stiffness_N_per_m = 2000.0;
  out->dof_in = 3;
  out->dof_out = 3;
  out->workspace_box_count = 1;
  for (int i = 0; i < 3; ++i) {
    out->workspace[0].min_m[i] = -0.1;
    out->workspace[0].max_m[i] = 0.1;
  }
  return MHD_OK;
}

inline mhd_status read(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err) {
  Device* d = device_of(self);
  ++d->reads;
  if (d->read_status == MHD_ERROR) {
    fail(err, "encoder cable unplugged");
    return MHD_ERROR;
  }
  out->timestamp_s = d->host->now_s(d->host->clock_context);
  out->p_D_tool_m[0] = d->tool_x_m;
  out->p_D_tool_m[1] = 0.02;
  out->p_D_tool_m[2] = -0.02;
  for (int i = 0; i < 3; ++i) out->v_D_tool_mps[i] = d->last_force_N[i];
  out->q_D_tool_wxyz[0] = 1.0;
  out->q_D_tool_wxyz[1] = out->q_D_tool_wxyz[2] = out->q_D_tool_wxyz[3] = 0.0;
  out->buttons = d->reads;
  // A C plugin may return any int; the host must cope (7 is no mhd_status).
  return static_cast<mhd_status>(d->read_status);
}

inline mhd_status write(mhd_plugin_instance* self, const mhd_device_command* command, mhd_error* /*err*/) {
  Device* d = device_of(self);
  for (int i = 0; i < 3; ++i) d->last_force_N[i] = command->force_D_N[i];
  return MHD_OK;
}

inline mhd_status simulate_until(mhd_plugin_instance* /*self*/, double /*t_s*/, mhd_error* /*err*/) { return MHD_OK; }

inline const mhd_param_decl kParams[] = {
    {"tool_x_m", MHD_PARAM_NUMBER, "m", 0u, 0.0, 0.0, nullptr, "0.05", "p_D_tool_m[0] that device_read returns"},
    {"max_force_N", MHD_PARAM_NUMBER, "N", 0u, 0.0, 0.0, nullptr, "8.5", "the force limit device_info reports"},
    {"read_status", MHD_PARAM_CHOICE, "", 0u, 0.0, 0.0, "ok|no_data|deactivate|error|bogus", "ok",
     "what device_read returns"},
    {"fail", MHD_PARAM_CHOICE, "", 0u, 0.0, 0.0, "start|stop", nullptr, "that call returns MHD_ERROR"},
};

/// The full, valid table (name from mhd_add_plugin's MHD_PLUGIN_NAME).
inline mhd_plugin_api make_api() {
  mhd_plugin_api api{};
  api.abi_version = MHD_PLUGIN_ABI_VERSION;
  api.struct_size = sizeof(mhd_plugin_api);
  api.kind = MHD_KIND_DEVICE;
  api.name = MHD_PLUGIN_NAME;
  api.version = "1.2.3";
  api.description = "test device";
  api.open = open;
  api.start = start;
  api.stop = stop;
  api.close = close;
  api.params = kParams;
  api.param_count = sizeof(kParams) / sizeof(kParams[0]);
  api.device_info = info;
  api.device_read = read;
  api.device_write = write;
  api.simulate_until = simulate_until;
  return api;
}

}  // namespace test_device
