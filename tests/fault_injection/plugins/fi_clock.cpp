// A display for the fault-injection suite's kill -9 test: at open it writes the host
// clock and CLOCK_MONOTONIC, read together, to `file` ("<host_now_s> <monotonic_s>"), so
// the parent process converts its own kill time into the recording's time base (both
// clocks are CLOCK_MONOTONIC: the host's counts from its own start). Draws nothing.
#include "probe_common.h"

#include <ctime>
#include <stdexcept>
#include <string>

namespace {

class FiClock {
 public:
  static constexpr std::array kParams{
      mhd::sdk::required_text("file", "where open() writes '<host_now_s> <monotonic_s>'"),
  };

  FiClock(const mhd_host& host, const mhd::sdk::Params& params) {
    const std::string file = params.text("file");
    timespec mono{};
    const double host_s = mhd::sdk::host_now(host);
    clock_gettime(CLOCK_MONOTONIC, &mono);
    std::FILE* f = std::fopen(file.c_str(), "w");
    if (f == nullptr) throw std::runtime_error("cannot write " + file);
    std::fprintf(f, "%.9f %.9f\n", host_s, static_cast<double>(mono.tv_sec) + 1e-9 * static_cast<double>(mono.tv_nsec));
    std::fclose(f);
  }

  void display_write(const mhd_display_frame&) {}
};

}  // namespace

MHD_PLUGIN_ENTRY(FiClock, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                           .description = "test display: writes the host clock's offset at open"})
