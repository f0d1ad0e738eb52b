#include "collision/huge_pages.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <utility>

namespace mhd {
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;

std::uintptr_t page_bytes() {
  static const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  return page;
}

/// The pages of `unit` bytes wholly inside [data, data+bytes), as (start, length); length 0 if none.
std::pair<void*, std::size_t> inner_pages(const void* data, std::size_t bytes, std::uintptr_t unit) {
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + unit - 1) / unit * unit;
  const std::uintptr_t last = (begin + bytes) / unit * unit;
  if (data == nullptr || last <= first) return {nullptr, 0};
  return {reinterpret_cast<void*>(first), static_cast<std::size_t>(last - first)};
}

}  // namespace

void advise_huge_pages(void* data, std::size_t bytes) {
  if (const auto [p, n] = inner_pages(data, bytes, kHugePage); n > 0) ::madvise(p, n, MADV_HUGEPAGE);
}

void populate_for_reading(const void* data, std::size_t bytes) {
  if (const auto [p, n] = inner_pages(data, bytes, page_bytes()); n > 0) ::madvise(p, n, MADV_POPULATE_READ);
}

void release_file_pages(const void* data, std::size_t bytes) {
  if (const auto [p, n] = inner_pages(data, bytes, page_bytes()); n > 0) ::madvise(p, n, MADV_DONTNEED);
}

}  // namespace mhd
