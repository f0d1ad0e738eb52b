#include "mesh_io/read_memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mhd {
namespace {

constexpr std::uint64_t kNoLimit = std::numeric_limits<std::uint64_t>::max();

// Bytes the process maps now (/proc/self/statm's first field), 0 if unknown.
std::uint64_t mapped_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return 0;
  unsigned long long pages = 0;
  const bool read = std::fscanf(f, "%llu", &pages) == 1;
  (void)std::fclose(f);
  const long page = ::sysconf(_SC_PAGESIZE);
  return read && page > 0 ? pages * static_cast<std::uint64_t>(page) : 0;
}

std::uint64_t sum_or_no_limit(std::uint64_t a, std::uint64_t b) { return b > kNoLimit - a ? kNoLimit : a + b; }

}  // namespace

ReadMemoryLimit::ReadMemoryLimit(std::uint64_t base_bytes, double per_file_byte, std::uint64_t cap_bytes)
    : per_file_byte_(std::isfinite(per_file_byte) ? std::max(per_file_byte, 0.0) : 0.0),
      cap_bytes_(cap_bytes == 0 ? kNoLimit : cap_bytes),
      allowance_(std::min(base_bytes, cap_bytes == 0 ? kNoLimit : cap_bytes)) {}

bool ReadMemoryLimit::start() {
  if (!kInThisBuild) return false;
  started_bytes_ = mapped_bytes();
  rlimit now{};
  if (started_bytes_ == 0 || ::getrlimit(RLIMIT_AS, &now) != 0) return false;
  // A lower limit set by the user (ulimit -v) stays the ceiling.
  ceiling_bytes_ = std::min<std::uint64_t>(now.rlim_max == RLIM_INFINITY ? kNoLimit : now.rlim_max,
                                           now.rlim_cur == RLIM_INFINITY ? kNoLimit : now.rlim_cur);
  started_ = apply();
  return started_;
}

bool ReadMemoryLimit::add_file(const std::string& path, std::uint64_t bytes) {
  if (!opened_.insert(path).second) return false;
  const double more = per_file_byte_ * static_cast<double>(bytes);
  const std::uint64_t grown = sum_or_no_limit(
      allowance_, more >= static_cast<double>(kNoLimit) ? kNoLimit : static_cast<std::uint64_t>(more));
  const std::uint64_t next = std::min(grown, cap_bytes_);
  if (next == allowance_) return false;
  allowance_ = next;
  if (started_) (void)apply();
  return true;
}

bool ReadMemoryLimit::apply() const {
  rlimit to{};
  if (::getrlimit(RLIMIT_AS, &to) != 0) return false;
  const std::uint64_t limit = std::min(sum_or_no_limit(started_bytes_, allowance_), ceiling_bytes_);
  to.rlim_cur = limit == kNoLimit ? RLIM_INFINITY : static_cast<rlim_t>(limit);  // the hard limit stays
  return ::setrlimit(RLIMIT_AS, &to) == 0;
}

}  // namespace mhd
