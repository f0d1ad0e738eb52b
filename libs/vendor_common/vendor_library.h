#pragma once
// A vendor's runtime library loaded when a plugin opens, as peers load SDKs that Debian
// lacks: the plugin is built without the SDK, declares the few documented C calls it makes
// and finds them with dlsym. A missing library or call is one error line that names the
// library, what the loader said, and how to install the runtime.

#include <stdexcept>
#include <string>

namespace mhd::vendor {

/// dlopen(library). Throws std::runtime_error
/// "cannot load <runtime> '<library>' (<loader's words>): <install_hint>".
void* open_library(const std::string& library, const char* runtime, const char* install_hint);
void close_library(void* handle) noexcept;

/// The address of `symbol`, or a throw "<runtime> '<library>' lacks <symbol> (...): <hint>".
void* find_symbol(void* handle, const std::string& library, const char* symbol, const char* runtime,
                  const char* install_hint);

/// Binds function pointers by name: bind("dhdOpen", calls.dhdOpen).
struct Binder {
  void* handle;
  const std::string& library;
  const char* runtime;
  const char* install_hint;
  template <class F>
  void operator()(const char* symbol, F*& out) const {
    out = reinterpret_cast<F*>(find_symbol(handle, library, symbol, runtime, install_hint));
  }
};

/// A vendor's runtime: the library loaded, and its calls bound by `bind_all`; unloaded
/// when it goes.
template <class Calls>
class Runtime {
 public:
  using BindAll = void (*)(const Binder& bind, Calls& calls);
  Runtime(const std::string& library, const char* runtime, const char* install_hint, BindAll bind_all)
      : handle_(open_library(library, runtime, install_hint)) {
    try {
      bind_all(Binder{handle_, library, runtime, install_hint}, calls_);
    } catch (...) {
      close_library(handle_);
      throw;
    }
  }
  ~Runtime() { close_library(handle_); }
  Runtime(const Runtime&) = delete;
  Runtime& operator=(const Runtime&) = delete;

  [[nodiscard]] const Calls& calls() const noexcept { return calls_; }

 private:
  void* handle_;
  Calls calls_{};
};

/// A vendor's error for the user: "<what> (<codes>): <vendor's words>; <advice>" (the
/// vendor's words left out when it gives none).
std::string describe_error(const std::string& what, const std::string& codes, const char* vendor_words,
                           const char* advice);

}  // namespace mhd::vendor
