#pragma once
// Whole reads and writes on a file descriptor: short transfers and EINTR are retried.

#include <unistd.h>

#include <cerrno>
#include <cstddef>

namespace mhd {

/// Reads exactly `size` bytes into `out`; false on an error or an early end of file.
inline bool read_all(int fd, void* out, std::size_t size) {
  auto* p = static_cast<char*>(out);
  while (size > 0) {
    const ssize_t n = ::read(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

/// Writes all `size` bytes of `data`; false on an error.
inline bool write_all(int fd, const void* data, std::size_t size) {
  const auto* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace mhd
