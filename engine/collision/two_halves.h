#pragma once
// Splits a long pass over [0, n) in two: the second half on a helper thread, the first
// here, for the load-time passes over large meshes (face normals, the cached tree's check).
// Never used on the haptic thread.

#include <cstddef>
#include <exception>
#include <future>
#include <system_error>

namespace mhd {

/// Calls f(first, last) on [0, n/2) and [n/2, n), on two threads when n is at least
/// `min_split` (one call over [0, n) otherwise, or where no thread can be started), and
/// returns whether every call returned true.
template <class F>
bool in_two_halves(std::size_t n, std::size_t min_split, F&& f) {
  if (n < min_split || n < 2) return f(std::size_t{0}, n);
  const std::size_t half = n / 2;
  std::future<bool> second;
  try {
    second = std::async(std::launch::async, [&f, half, n] { return f(half, n); });
  } catch (const std::system_error&) {
    return f(std::size_t{0}, n);
  }
  const bool first_ok = f(std::size_t{0}, half);
  return second.get() && first_ok;
}

}  // namespace mhd
