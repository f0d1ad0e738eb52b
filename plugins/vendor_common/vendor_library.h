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

}  // namespace mhd::vendor
