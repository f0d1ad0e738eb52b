// A base for the fault-injection suite: moves the host's simulated base with the twist it
// was last commanded (integrated at every base_read, no dynamics), so the tracker sees
// the base that is commanded; logs every command with its time; fails on cue.
// Parameters:
//   fault=none|nan|error|deactivate, fault_after_s (never), fault_on=read|write (read)
//     nan: base_read returns a NaN x_m; error: MHD_ERROR with a message
//   command_log=<path>  at close, one line per base_write: "t_s vx_mps vz_mps omega_radps",
//                       and a marker "t_s nan nan nan" when the fault strikes
#include "probe_common.h"

#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace {

struct Base {
  const mhd_host* host = nullptr;
  probe::Fault fault = probe::Fault::None;
  double fault_after_s = std::numeric_limits<double>::infinity();
  probe::FaultOn fault_on = probe::FaultOn::Read;
  probe::Log commands;
  double t_start_s = 0.0;
  double last_read_s = 0.0;
  mhd_base_command last{};

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

Base* of(mhd_plugin_instance* self) { return reinterpret_cast<Base*>(self); }

mhd_plugin_instance* open_base(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  return probe::guarded_open(err, [&] {
    if (host->sim_world == nullptr) throw std::runtime_error("fi_base moves the simulated base: the host has no sim_world");
    auto b = std::make_unique<Base>();
    b->host = host;
    std::string log;
    for (size_t i = 0; i < count; ++i) {
      const std::string name = params[i].name, value = params[i].value;
      if (name == "fault") b->fault = probe::fault_from(value);
      else if (name == "fault_after_s") b->fault_after_s = probe::number(name, value);
      else if (name == "fault_on") b->fault_on = probe::fault_on_from(value);
      else if (name == "command_log") log = value;
      else throw std::invalid_argument("unknown parameter '" + name + "'");
    }
    b->commands.open(log, 1u << 20);
    return b.release();
  });
}

mhd_status start(mhd_plugin_instance* self, mhd_error*) {
  Base& b = *of(self);
  b.t_start_s = b.last_read_s = probe::now_s(*b.host);
  return MHD_OK;
}

void close_base(mhd_plugin_instance* self) {
  of(self)->commands.write();
  delete of(self);
}

mhd_status read(mhd_plugin_instance* self, mhd_base_state* out, mhd_error* err) {
  Base& b = *of(self);
  const double t_s = probe::now_s(*b.host);
  const mhd_sim_world& w = *b.host->sim_world;
  double x = 0.0, z = 0.0, h = 0.0;
  w.get_base_pose(w.context, &x, &z, &h);
  // Base frame: x forward = (cos h, 0, -sin h), z = x cross y = (sin h, 0, cos h).
  const double dt = t_s - b.last_read_s;
  b.last_read_s = t_s;
  const double vx_W = b.last.vx_mps * std::cos(h) + b.last.vz_mps * std::sin(h);
  const double vz_W = -b.last.vx_mps * std::sin(h) + b.last.vz_mps * std::cos(h);
  x += vx_W * dt;
  z += vz_W * dt;
  h += b.last.omega_radps * dt;
  w.set_base_pose(w.context, x, z, h);
  *out = {};
  out->timestamp_s = t_s;
  out->x_m = x;
  out->z_m = z;
  out->heading_rad = h;
  out->vx_mps = vx_W;
  out->vz_mps = vz_W;
  out->omega_radps = b.last.omega_radps;
  if (b.fault_on == probe::FaultOn::Read && b.faulty(t_s)) {
    switch (b.fault) {
      case probe::Fault::Nan: out->x_m = std::numeric_limits<double>::quiet_NaN(); break;
      case probe::Fault::Error: probe::set_error(err, "injected fault: base controller not responding"); return MHD_ERROR;
      case probe::Fault::Deactivate: return MHD_DEACTIVATE;
      case probe::Fault::None: break;
    }
  }
  return MHD_OK;
}

mhd_status write(mhd_plugin_instance* self, const mhd_base_command* c, mhd_error* err) {
  Base& b = *of(self);
  b.commands.add(c->timestamp_s, c->vx_mps, c->vz_mps, c->omega_radps);
  b.last = *c;
  if (b.fault_on == probe::FaultOn::Write && b.faulty(probe::now_s(*b.host))) {
    if (b.fault == probe::Fault::Error) {
      probe::set_error(err, "injected fault: base controller not responding");
      return MHD_ERROR;
    }
    if (b.fault == probe::Fault::Deactivate) return MHD_DEACTIVATE;
  }
  return MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = probe::table("test base: moves the simulated base, logs every command, fails on cue");
    a.open = open_base;
    a.start = start;
    a.close = close_base;
    // Declared as text: this probe parses its own values, the host checks only the names.
    static const mhd_param_decl params[] = {
        {"fault", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"fault_after_s", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"fault_on", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"command_log", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
    };
    a.params = params;
    a.param_count = sizeof(params) / sizeof(params[0]);
    a.base_read = read;
    a.base_write = write;
    return a;
  }();
  return &api;
}
