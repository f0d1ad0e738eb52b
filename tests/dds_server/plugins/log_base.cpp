// A base for tests/dds_server: stands still at the origin and keeps every command it gets
// with the command's time stamp (the host clock, as the server's recording), written at
// close to `command_log` as lines "<timestamp_s> <vx_mps> <vz_mps> <omega_radps>". So a
// test sees when the server stopped the base, not only that it ended stopped.
#include <mhd/plugin_abi.h>

#include <cstdio>
#include <new>
#include <string>
#include <vector>

namespace {

struct Command {
  double t_s, vx_mps, vz_mps, omega_radps;
};

struct Base {
  const mhd_host* host = nullptr;
  std::string command_log;
  std::vector<Command> commands;  ///< reserved at open: base_write does not allocate
};

Base* of(mhd_plugin_instance* self) { return reinterpret_cast<Base*>(self); }

mhd_plugin_instance* open_base(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) try {
  auto* b = new Base;
  b->host = host;
  for (size_t i = 0; i < count; ++i) {
    const std::string name = params[i].name;
    if (name == "command_log") {
      b->command_log = params[i].value;
    } else {
      std::snprintf(err->message, sizeof(err->message), "unknown parameter '%s'", name.c_str());
      delete b;
      return nullptr;
    }
  }
  b->commands.reserve(1 << 16);  // 100 minutes of commands at 10 Hz
  return reinterpret_cast<mhd_plugin_instance*>(b);
} catch (const std::bad_alloc&) {
  std::snprintf(err->message, sizeof(err->message), "out of memory");
  return nullptr;
}

mhd_status ok(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }

void close_base(mhd_plugin_instance* self) {
  const Base& b = *of(self);
  if (!b.command_log.empty()) {
    if (std::FILE* f = std::fopen(b.command_log.c_str(), "w")) {
      for (const Command& c : b.commands) {
        std::fprintf(f, "%.9f %.17g %.17g %.17g\n", c.t_s, c.vx_mps, c.vz_mps, c.omega_radps);
      }
      std::fclose(f);
    }
  }
  delete of(self);
}

mhd_status read(mhd_plugin_instance* self, mhd_base_state* out, mhd_error*) {
  *out = {};
  out->timestamp_s = of(self)->host->now_s(of(self)->host->clock_context);
  return MHD_OK;
}

mhd_status write(mhd_plugin_instance* self, const mhd_base_command* c, mhd_error* err) {
  Base& b = *of(self);
  if (b.commands.size() == b.commands.capacity()) {
    std::snprintf(err->message, sizeof(err->message), "command log full");
    return MHD_ERROR;
  }
  b.commands.push_back({c->timestamp_s, c->vx_mps, c->vz_mps, c->omega_radps});
  return MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a{};
    a.abi_version = MHD_PLUGIN_ABI_VERSION;
    a.struct_size = sizeof(mhd_plugin_api);
    a.kind = MHD_PLUGIN_KIND;
    a.name = MHD_PLUGIN_NAME;
    a.version = "1.0.0";
    a.description = "test base that logs every command with its time";
    a.open = open_base;
    a.start = ok;
    a.stop = ok;
    a.close = close_base;
    static const mhd_param_decl params[] = {
        {"command_log", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "where every command is logged"},
    };
    a.params = params;
    a.param_count = 1;
    a.base_read = read;
    a.base_write = write;
    return a;
  }();
  return &api;
}
