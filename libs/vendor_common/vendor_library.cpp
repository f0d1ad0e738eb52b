#include "vendor_library.h"

#include <dlfcn.h>

namespace mhd::vendor {

void* open_library(const std::string& library, const char* runtime, const char* install_hint) {
  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("cannot load ") + runtime + " '" + library + "' (" +
                             (why != nullptr ? why : "unknown reason") + "): " + install_hint);
  }
  return handle;
}

void close_library(void* handle) noexcept {
  if (handle != nullptr) dlclose(handle);
}

void* find_symbol(void* handle, const std::string& library, const char* symbol, const char* runtime,
                  const char* install_hint) {
  dlerror();
  void* address = dlsym(handle, symbol);
  if (address == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(std::string(runtime) + " '" + library + "' lacks " + symbol + " (" +
                             (why != nullptr ? why : "no such symbol") + "): is it a supported version? " +
                             install_hint);
  }
  return address;
}

std::string describe_error(const std::string& what, const std::string& codes, const char* vendor_words,
                           const char* advice) {
  std::string out = what + " (" + codes + ")";
  if (vendor_words != nullptr && *vendor_words != '\0') out += std::string(": ") + vendor_words;
  return out + "; " + advice;
}

}  // namespace mhd::vendor
