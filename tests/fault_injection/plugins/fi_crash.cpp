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
#include <cstdint>
#include <cstdlib>
#include <exception>
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
  throw std::logic_error("crash '" + value + "' is declared but not handled");
}

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
    case Crash::Throw:
      // An exception no one catches: the SDK would turn one thrown out of display_write
      // into MHD_ERROR, so this one ends in std::terminate here, still the current
      // exception, as one escaping a hand-written plugin would.
      try {
        throw std::runtime_error("fi_crash: injected exception");
      } catch (...) {
        std::terminate();
      }
    case Crash::Exit0: std::exit(0);
  }
}

class FiCrash {
 public:
  static constexpr std::array kParams{
      [] {
        mhd_param_decl d = mhd::sdk::choice("crash", "segfault|bus|fpe|abort|throw|exit0", nullptr, "how it dies");
        d.flags |= MHD_PARAM_REQUIRED;
        return d;
      }(),
      mhd::sdk::integer("crash_on_call", "", "30", "the display_write that crashes", mhd::sdk::at_least(1)),
  };

  explicit FiCrash(const mhd::sdk::Params& params)
      : crash_(crash_from(params.text("crash"))), crash_on_call_(params.integer("crash_on_call")) {}

  void display_write(const mhd_display_frame&) {
    if (++calls_ == crash_on_call_) crash_now(crash_);
  }

 private:
  Crash crash_;
  std::uint64_t crash_on_call_;
  std::uint64_t calls_ = 0;
};

}  // namespace

MHD_PLUGIN_ENTRY(FiCrash,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "test display: crashes on its n-th frame (segfault, bus, fpe, abort, throw, exit0)"})
