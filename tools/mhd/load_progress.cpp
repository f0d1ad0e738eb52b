#include "load_progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <string>

namespace mhd::cli {

MeshProgress stderr_load_progress() {
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  return [terminal](std::string_view what, double fraction) {
    if (terminal) {
      fmt::print(stderr, "\r{} {:3.0f} %", what, 100.0 * fraction);
      if (fraction >= 1.0) fmt::print(stderr, "\n");
    } else if (fraction <= 0.0 || fraction >= 1.0) {
      fmt::print(stderr, "{} {:3.0f} %\n", what, 100.0 * fraction);
    }
  };
}

}  // namespace mhd::cli
