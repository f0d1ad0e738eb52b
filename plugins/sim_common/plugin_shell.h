#pragma once
// What every MHD plugin shell repeats: filling mhd_error, keeping C++ exceptions on
// this side of the C ABI, checking the host table, reading the host clock.

#include <mhd/plugin_abi.h>

#include <exception>
#include <string_view>

namespace mhd::plugin_support {

/// Copies message into err (truncated to fit, always NUL-terminated); err may be NULL.
void set_error(mhd_error* err, std::string_view message) noexcept;

/// Throws std::runtime_error unless host is a usable table of this ABI version with a clock.
void check_host(const mhd_host* host);

/// Throws std::runtime_error if the host gives a simulated world with a NULL function.
void check_sim_world(const mhd_host& host);

/// The host clock; throws std::runtime_error if it returns a non-finite time.
[[nodiscard]] double host_now(const mhd_host& host);

/// Runs f() -> mhd_status; an exception becomes MHD_ERROR with its message.
template <class F>
mhd_status guarded(mhd_error* err, F&& f) noexcept {
  try {
    return f();
  } catch (const std::exception& e) {
    set_error(err, e.what());
  } catch (...) {
    set_error(err, "unknown exception");
  }
  return MHD_ERROR;
}

/// Runs f() -> mhd_plugin_instance*; an exception becomes NULL with its message.
template <class F>
mhd_plugin_instance* guarded_open(mhd_error* err, F&& f) noexcept {
  try {
    return f();
  } catch (const std::exception& e) {
    set_error(err, e.what());
  } catch (...) {
    set_error(err, "unknown exception");
  }
  return nullptr;
}

}  // namespace mhd::plugin_support
