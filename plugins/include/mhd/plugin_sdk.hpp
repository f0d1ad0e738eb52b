// MHD plugin SDK: a plugin written as a C++ class, exported through the C ABI of
// mhd/plugin_abi.h (version 4). Header-only C++20. A plugin is its class plus one macro:
//
//   class Gripper {
//    public:
//     static constexpr std::array kParams{mhd::sdk::number("rate_hz", "Hz", "1000", "...", mhd::sdk::positive())};
//     Gripper(const mhd_host& host, const mhd::sdk::Params& params);  // or Gripper(const mhd::sdk::Params&)
//     void start();                                                    // optional
//     void stop();                                                     // optional
//     void device_info(mhd_device_info& out);
//     mhd_status device_read(mhd_device_state& out);                   // or void: MHD_OK
//     void device_write(const mhd_device_command& command);
//   };
//   MHD_PLUGIN_ENTRY(Gripper, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
//                              .description = "..."})
//
// What the SDK promises the class:
//   - open() checks the host table (ABI version, size, clock) and the scene's parameters
//     against kParams (mhd/plugin_sdk_params.hpp) before the constructor runs; the
//     constructor gets valid values only.
//   - No exception crosses the ABI: one thrown by the class becomes MHD_ERROR (NULL from
//     open) with its what() in mhd_error.
//   - One call at a time: a call that overlaps another on the same instance is refused
//     with "<name>: called while another call is under way" (no mutex: the device's calls
//     come from the haptic thread, which must never wait on a lock).
//   - The kind-specific calls, tracker_wait and simulate_until run only between start and
//     stop; before, "<name> is not started". device_info, counters, start and stop run
//     whenever the instance is open. stop() reaches the class only when it is started.
//   - NULL pointers from the host are refused with "<call>: NULL ..." before the class.
//   - Each table entry is set only when the class has the member (a requires-expression);
//     the others stay NULL, as the ABI wants for calls a kind does not make.
// What the class promises: members return mhd_status or void (void is MHD_OK); read and
// write calls never block (only tracker_wait may); the destructor is close().
//   tracker_read(std::span<mhd_tracker_sample>) -> std::size_t  samples written (0: MHD_NO_DATA)
//   tracker_read(std::span<mhd_tracker_sample>, std::size_t& count) -> mhd_status
//                                               the form for a tracker that can fail or
//                                               deactivate: count starts at 0, the status
//                                               is the call's
//   tracker_wait(double timeout_s)              -> mhd_status   MHD_OK with data, MHD_NO_DATA on timeout
//   counters(std::span<mhd_counter>)            -> std::size_t  counters the class keeps
//   base_read(mhd_base_state&), base_write(const mhd_base_command&),
//   display_write(const mhd_display_frame&), simulate_until(double t_s)
//   link_send(std::span<const mhd_link_message>)
//   link_read(std::span<mhd_link_message>)  -> std::size_t  messages written (0: MHD_NO_DATA)
//   link_read(std::span<mhd_link_message>, std::size_t& count) -> mhd_status
//                                               as tracker_read's form with a status
#ifndef MHD_PLUGIN_SDK_HPP
#define MHD_PLUGIN_SDK_HPP

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>
#include <mhd/plugin_sdk_params.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstring>
#include <exception>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace mhd::sdk {

/// What the table says of the plugin besides its calls.
struct PluginInfo {
  mhd_plugin_kind kind;
  const char* name;         ///< MHD_PLUGIN_NAME, so the table matches the file name
  const char* version;
  const char* description;  ///< one line
};

/// Copies message into err (cut to fit, always NUL-terminated); err may be NULL.
inline void set_error(mhd_error* err, std::string_view message) noexcept {
  if (err == nullptr) return;
  const std::size_t n = std::min(message.size(), sizeof(err->message) - 1);
  std::memcpy(err->message, message.data(), n);
  err->message[n] = '\0';
}

/// Throws std::runtime_error unless host is a usable table of this ABI version with a clock.
inline void check_host(const mhd_host* host) {
  if (host == nullptr) throw std::runtime_error("the host table is NULL");
  if (host->abi_version != MHD_PLUGIN_ABI_VERSION) {
    throw std::runtime_error("host ABI version " + std::to_string(host->abi_version) + " is not " +
                             std::to_string(MHD_PLUGIN_ABI_VERSION));
  }
  if (host->struct_size < sizeof(mhd_host)) {
    throw std::runtime_error("host table is " + std::to_string(host->struct_size) + " bytes, expected at least " +
                             std::to_string(sizeof(mhd_host)));
  }
  if (host->now_s == nullptr) throw std::runtime_error("the host gives no clock (now_s is NULL)");
}

/// The host clock, seconds; throws std::runtime_error if it returns a non-finite time.
[[nodiscard]] inline double host_now(const mhd_host& host) {
  const double t = host.now_s(host.clock_context);
  if (!std::isfinite(t)) throw std::runtime_error("the host clock returned a non-finite time");
  return t;
}

/// Runs f(); an exception becomes `failed` with its message in err.
template <class R, class F>
R guarded(mhd_error* err, R failed, F&& f) noexcept {
  try {
    return f();
  } catch (const std::exception& e) {
    set_error(err, e.what());
  } catch (...) {
    set_error(err, "unknown exception");
  }
  return failed;
}

namespace detail {

template <class P>
struct Instance {
  template <class... A>
  explicit Instance(A&&... a) : plugin(std::forward<A>(a)...) {}
  std::atomic<bool> in_call{false};
  bool started = false;
  P plugin;
};

template <class P>
constexpr std::span<const mhd_param_decl> params_of() {
  if constexpr (requires { P::kParams; }) {
    return std::span<const mhd_param_decl>(P::kParams.data(), P::kParams.size());
  } else {
    return {};
  }
}

/// Whether P's link_read reports its own status (and the count through a reference).
template <class P>
concept link_read_has_status = requires(P& p, std::span<mhd_link_message> o, std::size_t& n) {
  { p.link_read(o, n) } -> std::same_as<mhd_status>;
};

/// Whether P's tracker_read reports its own status (and the count through a reference).
template <class P>
concept tracker_read_has_status = requires(P& p, std::span<mhd_tracker_sample> o, std::size_t& n) {
  { p.tracker_read(o, n) } -> std::same_as<mhd_status>;
};

/// A member's result as a status: void is MHD_OK.
template <class F>
mhd_status status_of(F&& f) {
  if constexpr (std::is_void_v<decltype(f())>) {
    f();
    return MHD_OK;
  } else {
    return static_cast<mhd_status>(f());
  }
}

// The C functions of the table for class P, named I.name in messages.
template <class P, const PluginInfo& I>
struct Calls {
  using Inst = Instance<P>;
  enum class Need { Open, Running };

  template <class F>
  static mhd_status with(mhd_plugin_instance* self, Need need, mhd_error* err, F&& f) noexcept {
    return guarded(err, MHD_ERROR, [&]() -> mhd_status {
      if (self == nullptr) throw std::invalid_argument("instance is NULL");
      Inst& s = *reinterpret_cast<Inst*>(self);
      if (s.in_call.exchange(true, std::memory_order_acquire)) {
        throw std::logic_error(std::string(I.name) + ": called while another call is under way");
      }
      struct Leave {
        std::atomic<bool>& in_call;
        ~Leave() { in_call.store(false, std::memory_order_release); }
      } leave{s.in_call};
      if (need == Need::Running && !s.started) throw std::logic_error(std::string(I.name) + " is not started");
      return f(s);
    });
  }

  template <class T>
  static T& deref(T* p, const char* what) {
    if (p == nullptr) throw std::invalid_argument(what);
    return *p;
  }

  static mhd_plugin_instance* open(const mhd_host* host, const mhd_param* params, size_t count,
                                   mhd_error* err) noexcept {
    return guarded(err, static_cast<mhd_plugin_instance*>(nullptr), [&] {
      check_host(host);
      const Params values(params_of<P>(), params, count);
      Inst* s = nullptr;
      if constexpr (std::is_constructible_v<P, const mhd_host&, const Params&>) {
        s = new Inst(*host, values);
      } else {
        s = new Inst(values);
      }
      return reinterpret_cast<mhd_plugin_instance*>(s);
    });
  }
  static mhd_status start(mhd_plugin_instance* self, mhd_error* err) noexcept {
    return with(self, Need::Open, err, [](Inst& s) {
      mhd_status r = MHD_OK;
      if constexpr (requires { s.plugin.start(); }) r = status_of([&] { return s.plugin.start(); });
      s.started = r == MHD_OK;
      return r;
    });
  }
  static mhd_status stop(mhd_plugin_instance* self, mhd_error* err) noexcept {
    return with(self, Need::Open, err, [](Inst& s) {
      if (!std::exchange(s.started, false)) return MHD_OK;
      if constexpr (requires { s.plugin.stop(); }) return status_of([&] { return s.plugin.stop(); });
      return MHD_OK;
    });
  }
  static void close(mhd_plugin_instance* self) noexcept { delete reinterpret_cast<Inst*>(self); }

  /// A call with one pointer argument, which the host must not pass NULL: f(plugin, *arg).
  template <class T, class F>
  static mhd_status with_arg(mhd_plugin_instance* self, Need need, T* arg, const char* if_null, mhd_error* err,
                             F&& f) noexcept {
    return with(self, need, err, [&](Inst& s) {
      T& a = deref(arg, if_null);
      return status_of([&] { return f(s.plugin, a); });
    });
  }

  static mhd_status device_info(mhd_plugin_instance* self, mhd_device_info* out, mhd_error* err) noexcept {
    return with_arg(self, Need::Open, out, "device_info: out is NULL", err, [](P& p, auto& o) { return p.device_info(o); });
  }
  static mhd_status device_read(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err) noexcept {
    return with_arg(self, Need::Running, out, "device_read: out is NULL", err,
                    [](P& p, auto& o) { return p.device_read(o); });
  }
  static mhd_status device_write(mhd_plugin_instance* self, const mhd_device_command* c, mhd_error* err) noexcept {
    return with_arg(self, Need::Running, c, "device_write: command is NULL", err,
                    [](P& p, auto& command) { return p.device_write(command); });
  }
  static mhd_status tracker_read(mhd_plugin_instance* self, mhd_tracker_sample* out, size_t capacity, size_t* count,
                                 mhd_error* err) noexcept {
    return with(self, Need::Running, err, [&](Inst& s) {
      if (count == nullptr || (out == nullptr && capacity > 0)) throw std::invalid_argument("tracker_read: NULL output");
      const std::span<mhd_tracker_sample> samples(out, capacity);
      if constexpr (tracker_read_has_status<P>) {
        *count = 0;
        return s.plugin.tracker_read(samples, *count);
      } else {
        *count = s.plugin.tracker_read(samples);
        return *count > 0 ? MHD_OK : MHD_NO_DATA;
      }
    });
  }
  static mhd_status tracker_wait(mhd_plugin_instance* self, double timeout_s, mhd_error* err) noexcept {
    return with(self, Need::Running, err, [&](Inst& s) { return s.plugin.tracker_wait(timeout_s); });
  }
  static mhd_status base_read(mhd_plugin_instance* self, mhd_base_state* out, mhd_error* err) noexcept {
    return with_arg(self, Need::Running, out, "base_read: out is NULL", err, [](P& p, auto& o) { return p.base_read(o); });
  }
  static mhd_status base_write(mhd_plugin_instance* self, const mhd_base_command* c, mhd_error* err) noexcept {
    return with_arg(self, Need::Running, c, "base_write: command is NULL", err,
                    [](P& p, auto& command) { return p.base_write(command); });
  }
  static mhd_status display_write(mhd_plugin_instance* self, const mhd_display_frame* f, mhd_error* err) noexcept {
    return with_arg(self, Need::Running, f, "display_write: NULL frame", err,
                    [](P& p, auto& frame) { return p.display_write(frame); });
  }
  static mhd_status link_send(mhd_plugin_instance* self, const mhd_link_message* messages, size_t count,
                              mhd_error* err) noexcept {
    return with(self, Need::Running, err, [&](Inst& s) {
      if (messages == nullptr && count > 0) throw std::invalid_argument("link_send: NULL messages");
      return status_of([&] { return s.plugin.link_send(std::span<const mhd_link_message>(messages, count)); });
    });
  }
  static mhd_status link_read(mhd_plugin_instance* self, mhd_link_message* out, size_t capacity, size_t* count,
                              mhd_error* err) noexcept {
    return with(self, Need::Running, err, [&](Inst& s) {
      if (count == nullptr || (out == nullptr && capacity > 0)) throw std::invalid_argument("link_read: NULL output");
      const std::span<mhd_link_message> messages(out, capacity);
      if constexpr (link_read_has_status<P>) {
        *count = 0;
        return s.plugin.link_read(messages, *count);
      } else {
        *count = s.plugin.link_read(messages);
        return *count > 0 ? MHD_OK : MHD_NO_DATA;
      }
    });
  }
  static mhd_status simulate_until(mhd_plugin_instance* self, double t_s, mhd_error* err) noexcept {
    return with(self, Need::Running, err, [&](Inst& s) { return status_of([&] { return s.plugin.simulate_until(t_s); }); });
  }
  static mhd_status counters(mhd_plugin_instance* self, mhd_counter* out, size_t capacity, size_t* count,
                             mhd_error* err) noexcept {
    return with(self, Need::Open, err, [&](Inst& s) {
      if (count == nullptr || (out == nullptr && capacity > 0)) throw std::invalid_argument("counters: NULL output");
      *count = s.plugin.counters(std::span<mhd_counter>(out, capacity));
      return MHD_OK;
    });
  }
};

}  // namespace detail

/// The table of class P: every entry whose member P has, the others NULL. kParams, when
/// P declares it, is the table's parameter list.
template <class P, const PluginInfo& I>
constexpr mhd_plugin_api plugin_table() {
  using C = detail::Calls<P, I>;
  constexpr std::span<const mhd_param_decl> params = detail::params_of<P>();
  static_assert(I.kind != MHD_KIND_DEVICE ||
                    requires(P& p, mhd_device_info& i, mhd_device_state& s, const mhd_device_command& c) {
                      p.device_info(i);
                      p.device_read(s);
                      p.device_write(c);
                    },
                "a device plugin needs device_info, device_read and device_write");
  // Members a designated initialiser leaves out are value-initialised (NULL), as wanted
  // here; GCC's -Wmissing-field-initializers warns about it all the same.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
  mhd_plugin_api t{
      .abi_version = MHD_PLUGIN_ABI_VERSION,
      .struct_size = sizeof(mhd_plugin_api),
      .kind = I.kind,
      .name = I.name,
      .version = I.version,
      .description = I.description,
      .open = C::open,
      .start = C::start,
      .stop = C::stop,
      .close = C::close,
      .params = params.empty() ? nullptr : params.data(),
      .param_count = params.size(),
  };
#pragma GCC diagnostic pop
  // Each kind entry is set only when P has the member (if constexpr, not ?:, so the calls
  // of members P lacks are never instantiated).
  if constexpr (requires(P& p, mhd_device_info& o) { p.device_info(o); }) t.device_info = C::device_info;
  if constexpr (requires(P& p, mhd_device_state& o) { p.device_read(o); }) t.device_read = C::device_read;
  if constexpr (requires(P& p, const mhd_device_command& c) { p.device_write(c); }) t.device_write = C::device_write;
  if constexpr (requires(P& p, std::span<mhd_tracker_sample> o) { p.tracker_read(o); } ||
                detail::tracker_read_has_status<P>) {
    t.tracker_read = C::tracker_read;
  }
  if constexpr (requires(P& p, mhd_base_state& o) { p.base_read(o); }) t.base_read = C::base_read;
  if constexpr (requires(P& p, const mhd_base_command& c) { p.base_write(c); }) t.base_write = C::base_write;
  if constexpr (requires(P& p, const mhd_display_frame& f) { p.display_write(f); }) t.display_write = C::display_write;
  if constexpr (requires(P& p) { p.simulate_until(0.0); }) t.simulate_until = C::simulate_until;
  if constexpr (requires(P& p) { p.tracker_wait(0.0); }) t.tracker_wait = C::tracker_wait;
  if constexpr (requires(P& p, std::span<mhd_counter> o) { p.counters(o); }) t.counters = C::counters;
  if constexpr (requires(P& p, std::span<const mhd_link_message> m) { p.link_send(m); }) t.link_send = C::link_send;
  if constexpr (requires(P& p, std::span<mhd_link_message> o) { p.link_read(o); } || detail::link_read_has_status<P>) {
    t.link_read = C::link_read;
  }
  return t;
}

/// What mhd_plugin_entry returns: the table for a host of this ABI version, else NULL.
constexpr const mhd_plugin_api* entry(const mhd_plugin_api& table, uint32_t host_abi_version) noexcept {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &table : nullptr;
}

}  // namespace mhd::sdk

/// Exports mhd_plugin_entry for class `Class` (its full name) with the PluginInfo given as
/// a braced list; write it once, at global scope, in one source file of the plugin. The
/// table lives in an unnamed namespace: a static inside a template or inline function
/// would be a GNU unique symbol, which dlclose cannot unload.
#define MHD_PLUGIN_ENTRY(Class, ...)                                                                     \
  namespace {                                                                                            \
  constexpr ::mhd::sdk::PluginInfo mhd_plugin_info_ __VA_ARGS__;                                         \
  constexpr mhd_plugin_api mhd_plugin_table_ = ::mhd::sdk::plugin_table<Class, mhd_plugin_info_>();      \
  }                                                                                                      \
  extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {       \
    return ::mhd::sdk::entry(mhd_plugin_table_, host_abi_version);                                       \
  }

#endif  // MHD_PLUGIN_SDK_HPP
