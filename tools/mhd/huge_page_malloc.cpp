#include "huge_page_malloc.h"

#include <sys/auxv.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <string_view>

namespace mhd::cli {

bool wants_huge_page_malloc(const char* subcommand) {
  if (subcommand == nullptr) return false;
  const std::string_view name = subcommand;
  for (const std::string_view offline : {"validate", "strokes", "proxy-replay", "plan-sim", "share-sim", "cache"}) {
    if (name == offline) return true;
  }
  return false;
}

void restart_with_huge_page_malloc(const char* program, char** argv) {
#if defined(__GLIBC__)
  constexpr std::string_view kTunable = "glibc.malloc.hugetlb";
  // Secure execution drops GLIBC_TUNABLES from the environment: it would restart forever.
  if (::getauxval(AT_SECURE) != 0) return;
  const char* given = std::getenv("GLIBC_TUNABLES");
  const std::string before = given != nullptr ? given : "";
  if (before.find(kTunable) != std::string::npos) return;
  const std::string after = (before.empty() ? "" : before + ":") + std::string(kTunable) + "=1";
  if (::setenv("GLIBC_TUNABLES", after.c_str(), 1) != 0) return;
  ::execv(program, argv);
  // Not restarted: go on as started, with the environment as it was.
  if (given != nullptr) {
    ::setenv("GLIBC_TUNABLES", before.c_str(), 1);
  } else {
    ::unsetenv("GLIBC_TUNABLES");
  }
#else
  (void)program;
  (void)argv;
#endif
}

}  // namespace mhd::cli
