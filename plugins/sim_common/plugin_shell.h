#pragma once
// What every MHD plugin shell repeats: filling mhd_error, keeping C++ exceptions on
// this side of the C ABI, checking the host table, reading the host clock.

#include <mhd/plugin_abi.h>

#include <atomic>
#include <exception>
#include <stdexcept>
#include <string>
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

/// What a call needs of the instance: only that it is open, or that it runs (started).
enum class Need { Open, Running };

/// The frame of every instance call of a shell: the plugin's Instance (a struct with
/// `std::atomic<bool> in_call` and `bool started`) is taken from `self`, marked in a call
/// and, for Need::Running, checked to be started ("<plugin> is not started"); then
/// f(instance) runs as guarded() does.
///
/// No mutex: the device's calls come from the haptic thread, which must never wait on a
/// lock, and the host makes an instance's calls one at a time (the ABI's rule). A call
/// that overlaps another one (a host breaking that rule, or the last-gasp path after a
/// crash inside a call) is refused with "<plugin>: called while another call is under way"
/// instead of racing the first or deadlocking on it.
template <class Instance, class F>
mhd_status with_instance(std::string_view plugin, mhd_plugin_instance* self, Need need, mhd_error* err,
                         F&& f) noexcept {
  return guarded(err, [&]() -> mhd_status {
    if (self == nullptr) throw std::invalid_argument("instance is NULL");
    Instance& instance = *reinterpret_cast<Instance*>(self);
    if (instance.in_call.exchange(true, std::memory_order_acquire)) {
      throw std::logic_error(std::string(plugin) + ": called while another call is under way");
    }
    struct Leave {
      std::atomic<bool>& in_call;
      ~Leave() { in_call.store(false, std::memory_order_release); }
    } leave{instance.in_call};
    if (need == Need::Running && !instance.started) throw std::logic_error(std::string(plugin) + " is not started");
    return f(instance);
  });
}

}  // namespace mhd::plugin_support
