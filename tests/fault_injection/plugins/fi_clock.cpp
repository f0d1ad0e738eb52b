// A display for the fault-injection suite's kill -9 test: at open it writes the host
// clock and CLOCK_MONOTONIC, read together, to `file` ("<host_now_s> <monotonic_s>"), so
// the parent process converts its own kill time into the recording's time base (both
// clocks are CLOCK_MONOTONIC: the host's counts from its own start). Draws nothing.
#include "probe_common.h"

#include <ctime>
#include <string>

namespace {

struct Probe {};

mhd_plugin_instance* open_probe(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  return probe::guarded_open(err, [&] {
    std::string file;
    for (size_t i = 0; i < count; ++i) {
      const std::string name = params[i].name;
      if (name == "file") file = params[i].value;
      else throw std::invalid_argument("unknown parameter '" + name + "'");
    }
    if (file.empty()) throw std::invalid_argument("parameter 'file' is required");
    timespec mono{};
    const double host_s = probe::now_s(*host);
    clock_gettime(CLOCK_MONOTONIC, &mono);
    std::FILE* f = std::fopen(file.c_str(), "w");
    if (f == nullptr) throw std::runtime_error("cannot write " + file);
    std::fprintf(f, "%.9f %.9f\n", host_s, static_cast<double>(mono.tv_sec) + 1e-9 * static_cast<double>(mono.tv_nsec));
    std::fclose(f);
    return new Probe;
  });
}

void close_probe(mhd_plugin_instance* self) { delete reinterpret_cast<Probe*>(self); }

mhd_status write(mhd_plugin_instance*, const mhd_display_frame*, mhd_error*) { return MHD_OK; }

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = probe::table("test display: writes the host clock's offset at open");
    a.open = open_probe;
    a.close = close_probe;
    // Declared as text: this probe parses its own values, the host checks only the names.
    static const mhd_param_decl params[] = {
        {"file", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
    };
    a.params = params;
    a.param_count = sizeof(params) / sizeof(params[0]);
    a.display_write = write;
    return a;
  }();
  return &api;
}
