// A Cartesian device for the fault-injection suite: its tool follows a script (held at
// p_free_m, then moved to p_press_m over press_ramp_s from press_at_s, device frame, so a test
// places a surface between the two HIPs and the device presses into it), it logs every
// command with its time, and it fails on cue.
// Parameters:
//   p_free_m, p_press_m   "x y z" (default: a PHANToM's tool at joint angles 0 0.3 0.2)
//   press_at_s (never), press_ramp_s (0.05)   seconds after start
//   fault=none|nan|error|deactivate, fault_after_s (never), fault_on=read|write (read)
//     nan: p_D_tool_m[1] is NaN (read only); error: MHD_ERROR with a message
//   command_log=<path>  at close, one line per device_write: "t_s fx fy fz" (N, device frame), and
//                       a marker "t_s nan nan nan" when the fault strikes
#include "probe_common.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <string>

namespace {

struct Device {
  const mhd_host* host = nullptr;
  double p_free[3] = {0.0, 0.06610330791925151, 0.032271919564375806};
  double p_press[3] = {0.0, 0.06610330791925151, 0.032271919564375806};
  double press_at_s = std::numeric_limits<double>::infinity();
  double press_ramp_s = 0.05;
  probe::Fault fault = probe::Fault::None;
  double fault_after_s = std::numeric_limits<double>::infinity();
  probe::FaultOn fault_on = probe::FaultOn::Read;
  probe::Log commands;
  double t_start_s = 0.0;

  bool marked = false;

  /// True from fault_after_s on; the first time, a marker row "t_s nan nan nan" goes into
  /// the command log, so a test knows when the fault struck.
  bool faulty(double t_s) {
    if (fault == probe::Fault::None || t_s - t_start_s < fault_after_s) return false;
    if (!marked) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      commands.add(t_s, nan, nan, nan);
      marked = true;
    }
    return true;
  }
};

Device* of(mhd_plugin_instance* self) { return reinterpret_cast<Device*>(self); }

mhd_plugin_instance* open_device(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  return probe::guarded_open(err, [&] {
    auto d = std::make_unique<Device>();
    d->host = host;
    std::string log;
    for (size_t i = 0; i < count; ++i) {
      const std::string name = params[i].name, value = params[i].value;
      if (name == "p_free_m") probe::vector3(name, value, d->p_free);
      else if (name == "p_press_m") probe::vector3(name, value, d->p_press);
      else if (name == "press_at_s") d->press_at_s = probe::number(name, value);
      else if (name == "press_ramp_s") d->press_ramp_s = probe::number(name, value);
      else if (name == "fault") d->fault = probe::fault_from(value);
      else if (name == "fault_after_s") d->fault_after_s = probe::number(name, value);
      else if (name == "fault_on") d->fault_on = probe::fault_on_from(value);
      else if (name == "command_log") log = value;
      else throw std::invalid_argument("unknown parameter '" + name + "'");
    }
    d->commands.open(log, 1u << 17);  // 131 s at 1 kHz
    return d.release();
  });
}

mhd_status start(mhd_plugin_instance* self, mhd_error*) {
  of(self)->t_start_s = probe::now_s(*of(self)->host);
  return MHD_OK;
}

void close_device(mhd_plugin_instance* self) {
  of(self)->commands.write();
  delete of(self);
}

mhd_status read(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err) {
  Device& d = *of(self);
  const double t_s = probe::now_s(*d.host);
  *out = {};
  out->timestamp_s = t_s;
  const double s = d.press_ramp_s > 0.0 ? std::clamp((t_s - d.t_start_s - d.press_at_s) / d.press_ramp_s, 0.0, 1.0)
                                        : (t_s - d.t_start_s >= d.press_at_s ? 1.0 : 0.0);
  for (int i = 0; i < 3; ++i) out->p_D_tool_m[i] = d.p_free[i] + s * (d.p_press[i] - d.p_free[i]);
  out->q_D_tool_wxyz[0] = 1.0;
  if (d.fault_on == probe::FaultOn::Read && d.faulty(t_s)) {
    switch (d.fault) {
      case probe::Fault::Nan: out->p_D_tool_m[1] = std::numeric_limits<double>::quiet_NaN(); break;
      case probe::Fault::Error: probe::set_error(err, "injected fault: encoder read failed"); return MHD_ERROR;
      case probe::Fault::Deactivate: return MHD_DEACTIVATE;
      case probe::Fault::None: break;
    }
  }
  return MHD_OK;
}

mhd_status write(mhd_plugin_instance* self, const mhd_device_command* c, mhd_error* err) {
  Device& d = *of(self);
  d.commands.add(c->timestamp_s, c->force_D_N[0], c->force_D_N[1], c->force_D_N[2]);
  if (d.fault_on == probe::FaultOn::Write && d.faulty(probe::now_s(*d.host))) {
    if (d.fault == probe::Fault::Error) {
      probe::set_error(err, "injected fault: amplifier not responding");
      return MHD_ERROR;
    }
    if (d.fault == probe::Fault::Deactivate) return MHD_DEACTIVATE;
  }
  return MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = probe::table("test device: scripted tool path, logs every command, fails on cue");
    static const mhd_param_decl params[] = {
        {"p_free_m", MHD_PARAM_VECTOR3, "m", 0u, 0.0, 0.0, nullptr, nullptr, "the tool before the press"},
        {"p_press_m", MHD_PARAM_VECTOR3, "m", 0u, 0.0, 0.0, nullptr, nullptr, "the tool pressing"},
        {"press_at_s", MHD_PARAM_NUMBER, "s", 0u, 0.0, 0.0, nullptr, nullptr, "when the press starts"},
        {"press_ramp_s", MHD_PARAM_NUMBER, "s", 0u, 0.0, 0.0, nullptr, "0.05", "how long it takes"},
        {"fault", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "none|nan|error|deactivate"},
        {"fault_after_s", MHD_PARAM_NUMBER, "s", 0u, 0.0, 0.0, nullptr, nullptr, "when the fault strikes"},
        {"fault_on", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "read|write"},
        {"command_log", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "where close() writes the commands"},
    };
    a.params = params;
    a.param_count = sizeof(params) / sizeof(params[0]);
    a.open = open_device;
    a.start = start;
    a.close = close_device;
    a.device_info = probe::phantom_like_info;
    a.device_read = read;
    a.device_write = write;
    return a;
  }();
  return &api;
}
