// A display for the fault-injection suite that kills its process the way broken plugin
// code does, on its crash_on_call-th display_write (60 Hz: call 30 is about 0.5 s in).
// Parameters:
//   crash=segfault|bus|fpe|abort|throw|exit0   (required)
//   crash_on_call=<n>                           (default 30)
#include "probe_common.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

namespace {

enum class Crash { Segfault, Bus, Fpe, Abort, Throw, Exit0 };

Crash crash_from(const std::string& value) {
  if (value == "segfault") return Crash::Segfault;
  if (value == "bus") return Crash::Bus;
  if (value == "fpe") return Crash::Fpe;
  if (value == "abort") return Crash::Abort;
  if (value == "throw") return Crash::Throw;
  if (value == "exit0") return Crash::Exit0;
  throw std::invalid_argument("bad crash '" + value + "' (segfault, bus, fpe, abort, throw, exit0)");
}

struct Crasher {
  Crash crash = Crash::Segfault;
  long crash_on_call = 30;
  long calls = 0;
};

Crasher* of(mhd_plugin_instance* self) { return reinterpret_cast<Crasher*>(self); }

int* volatile g_nowhere = nullptr;
volatile int g_zero = 0;

[[noreturn]] void bus_error() {
  // A read past the end of a mapped file: SIGBUS, as from a device's vanished memory.
  char name[] = "/tmp/fi_crash_XXXXXX";
  const int fd = ::mkstemp(name);
  ::unlink(name);
  void* page = ::mmap(nullptr, 4096, PROT_READ, MAP_SHARED, fd, 0);
  volatile const char* p = static_cast<const char*>(page);
  (void)p[0];
  ::raise(SIGBUS);  // where the read did not trap
  std::abort();
}

void crash_now(Crash crash) {
  switch (crash) {
    case Crash::Segfault: *g_nowhere = 1; break;
    case Crash::Bus: bus_error();
    case Crash::Fpe: {
#if defined(__x86_64__) || defined(__i386__)
      volatile int quotient = 1 / g_zero;  // traps on x86
      (void)quotient;
#endif
      ::raise(SIGFPE);
      break;
    }
    case Crash::Abort: std::abort();
    case Crash::Throw: throw std::runtime_error("fi_crash: injected exception");
    case Crash::Exit0: std::exit(0);
  }
}

mhd_plugin_instance* open_crasher(const mhd_host*, const mhd_param* params, size_t count, mhd_error* err) {
  return probe::guarded_open(err, [&] {
    auto c = std::make_unique<Crasher>();
    bool given = false;
    for (size_t i = 0; i < count; ++i) {
      const std::string name = params[i].name, value = params[i].value;
      if (name == "crash") {
        c->crash = crash_from(value);
        given = true;
      } else if (name == "crash_on_call") {
        c->crash_on_call = static_cast<long>(probe::number(name, value));
      } else {
        throw std::invalid_argument("unknown parameter '" + name + "'");
      }
    }
    if (!given) throw std::invalid_argument("parameter 'crash' is required");
    return c.release();
  });
}

void close_crasher(mhd_plugin_instance* self) { delete of(self); }

mhd_status write(mhd_plugin_instance* self, const mhd_display_frame*, mhd_error*) {
  Crasher& c = *of(self);
  if (++c.calls == c.crash_on_call) crash_now(c.crash);
  return MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = probe::table("test display: crashes on its n-th frame (segfault, bus, fpe, abort, throw, exit0)");
    a.open = open_crasher;
    a.close = close_crasher;
    // Declared as text: this probe parses its own values, the host checks only the names.
    static const mhd_param_decl params[] = {
        {"crash", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"crash_on_call", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
    };
    a.params = params;
    a.param_count = sizeof(params) / sizeof(params[0]);
    a.display_write = write;
    return a;
  }();
  return &api;
}
