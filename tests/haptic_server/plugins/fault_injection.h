#pragma once
// Shared by the haptic server's fault-injection test plugins: parameters
//   fail_after_reads=<n>   reads that succeed before the fault (default: never fail)
//   fault=nan|huge|error|deactivate|block|none   what the read returns from then on (block:
//                          the first faulty read sleeps block_s, then succeeds; huge: a
//                          finite but absurd value, 1e30, where nan would be NaN)
//   block_s=<seconds>      how long a blocking read blocks (default 1)
//   command_log=<path>     on close, the last command received is written there as
//                          "<count> <a> <b> <c>\n" (count of commands, then the values)
// so a test can check, from the plugin's side, what the host left the hardware with.

#include <mhd/plugin_abi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <string>
#include <thread>

namespace fault_injection {

enum class Fault { None, Nan, Huge, Error, Deactivate, Block };

struct Config {
  unsigned long fail_after_reads = ~0ul;
  Fault fault = Fault::None;
  std::string command_log;
  double last_command[3] = {0.0, 0.0, 0.0};
  unsigned long commands = 0;
  unsigned long reads = 0;
  double block_s = 1.0;
  bool blocked = false;
};

inline void fail(mhd_error* err, const std::string& text) {
  std::snprintf(err->message, sizeof(err->message), "%s", text.c_str());
}

/// False (with err filled) for an unknown parameter or a bad value.
inline bool parse(Config& c, const mhd_param* params, size_t count, mhd_error* err) {
  for (size_t i = 0; i < count; ++i) {
    const std::string name = params[i].name, value = params[i].value;
    if (name == "fail_after_reads") {
      c.fail_after_reads = std::strtoul(value.c_str(), nullptr, 10);
    } else if (name == "fault") {
      if (value == "nan") c.fault = Fault::Nan;
      else if (value == "huge") c.fault = Fault::Huge;
      else if (value == "error") c.fault = Fault::Error;
      else if (value == "deactivate") c.fault = Fault::Deactivate;
      else if (value == "block") c.fault = Fault::Block;
      else if (value == "none") c.fault = Fault::None;
      else {
        fail(err, "bad fault '" + value + "'");
        return false;
      }
    } else if (name == "block_s") {
      c.block_s = std::strtod(value.c_str(), nullptr);
    } else if (name == "command_log") {
      c.command_log = value;
    } else {
      fail(err, "unknown parameter '" + name + "'");
      return false;
    }
  }
  return true;
}

/// What this read returns: MHD_OK, or the fault once fail_after_reads reads have passed.
/// `nan_out` is set when the read must report NaN (or, with fault=huge, 1e30: see absurd()).
inline mhd_status next_read(Config& c, bool& nan_out, mhd_error* err) {
  nan_out = false;
  if (++c.reads <= c.fail_after_reads || c.fault == Fault::None) return MHD_OK;
  switch (c.fault) {
    case Fault::Nan:
    case Fault::Huge: nan_out = true; return MHD_OK;
    case Fault::Error: fail(err, "injected fault: hardware not responding"); return MHD_ERROR;
    case Fault::Deactivate: return MHD_DEACTIVATE;
    case Fault::Block:
      if (!c.blocked) {
        c.blocked = true;
        std::this_thread::sleep_for(std::chrono::duration<double>(c.block_s));
      }
      return MHD_OK;
    case Fault::None: break;
  }
  return MHD_OK;
}

/// The value a faulty read reports in place of a good one: NaN, or 1e30 with fault=huge.
inline double absurd(const Config& c) {
  return c.fault == Fault::Huge ? 1e30 : std::numeric_limits<double>::quiet_NaN();
}

inline void record(Config& c, double a, double b, double d) {
  c.last_command[0] = a;
  c.last_command[1] = b;
  c.last_command[2] = d;
  ++c.commands;
}

inline void write_log(const Config& c) {
  if (c.command_log.empty()) return;
  if (std::FILE* f = std::fopen(c.command_log.c_str(), "w")) {
    std::fprintf(f, "%lu %.17g %.17g %.17g\n", c.commands, c.last_command[0], c.last_command[1], c.last_command[2]);
    std::fclose(f);
  }
}

/// One opened fault plugin: its host and configuration (both plugins are this).
struct Instance {
  const mhd_host* host = nullptr;
  Config config;
};

inline Instance* of(mhd_plugin_instance* self) { return reinterpret_cast<Instance*>(self); }

inline mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t count,
                                          mhd_error* err) {
  auto* instance = new (std::nothrow) Instance;
  if (instance == nullptr) return nullptr;
  instance->host = host;
  if (!parse(instance->config, params, count, err)) {
    delete instance;
    return nullptr;
  }
  return reinterpret_cast<mhd_plugin_instance*>(instance);
}

inline mhd_status no_op(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }

/// Writes the command log, then frees the instance.
inline void close_instance(mhd_plugin_instance* self) {
  write_log(of(self)->config);
  delete of(self);
}

inline const mhd_param_decl kParams[] = {
    {"fail_after_reads", MHD_PARAM_INTEGER, "", 0u, 0.0, 0.0, nullptr, nullptr, "reads that succeed before the fault"},
    {"fault", MHD_PARAM_CHOICE, "", 0u, 0.0, 0.0, "nan|huge|error|deactivate|block|none", "none",
     "what the read returns from then on"},
    {"block_s", MHD_PARAM_NUMBER, "s", MHD_PARAM_HAS_MIN, 0.0, 0.0, nullptr, "1", "how long a blocking read blocks"},
    {"command_log", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "where close() writes the last command"},
};

/// A PHANToM Premium 1.5's device_info (its workspace box in the device frame).
inline mhd_status phantom_like_info(mhd_plugin_instance*, mhd_device_info* out, mhd_error*) {
  *out = mhd_device_info{};
  out->max_force_N = 8.5;
  out->max_stiffness_N_per_m = 3500.0;
  out->dof_in = 3;
  out->dof_out = 3;
  out->workspace_box_count = 1;
  const double lo[3] = {-0.1905, -0.0035, -0.1055}, hi[3] = {0.1905, 0.2635, 0.0855};
  for (int i = 0; i < 3; ++i) {
    out->workspace[0].min_m[i] = lo[i];
    out->workspace[0].max_m[i] = hi[i];
  }
  return MHD_OK;
}

/// The table both plugins start from: lifecycle filled, the kind's calls left to them.
inline mhd_plugin_api base_table(mhd_plugin_kind kind, const char* name) {
  mhd_plugin_api a{};
  a.abi_version = MHD_PLUGIN_ABI_VERSION;
  a.struct_size = sizeof(mhd_plugin_api);
  a.kind = kind;
  a.name = name;
  a.version = "1.0.0";
  a.description = "test plugin that fails on cue";
  a.open = open_instance;
  a.start = no_op;
  a.stop = no_op;
  a.close = close_instance;
  a.params = kParams;
  a.param_count = sizeof(kParams) / sizeof(kParams[0]);
  return a;
}

}  // namespace fault_injection
