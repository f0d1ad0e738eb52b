// null_display: the smallest useful MHD plugin, written as a third party would. A
// display that draws nothing and counts the frames it is given; with verbose=true it
// prints the count to stderr on stop. It includes only <mhd/plugin_abi.h> and builds
// either with mhd_add_plugin (CMakeLists.txt) or with plain g++ (docs/plugins.md).

#include <mhd/plugin_abi.h>

#include <cstdio>
#include <cstring>
#include <new>

namespace {

struct NullDisplay {
  unsigned long long frames = 0;
  bool verbose = false;
};

NullDisplay* self_of(mhd_plugin_instance* self) { return reinterpret_cast<NullDisplay*>(self); }

void set_error(mhd_error* err, const char* what, const char* detail) {
  std::snprintf(err->message, sizeof(err->message), "%s%s", what, detail);
}

mhd_plugin_instance* display_open(const mhd_host* /*host*/, const mhd_param* params, size_t param_count,
                                  mhd_error* err) {
  bool verbose = false;
  for (size_t i = 0; i < param_count; ++i) {
    if (std::strcmp(params[i].name, "verbose") != 0) {
      std::snprintf(err->message, sizeof(err->message), "unknown parameter '%s'", params[i].name);
      return nullptr;
    }
    if (std::strcmp(params[i].value, "true") == 0) {
      verbose = true;
    } else if (std::strcmp(params[i].value, "false") == 0) {
      verbose = false;
    } else {
      set_error(err, "verbose must be true or false, not ", params[i].value);
      return nullptr;
    }
  }
  auto* display = new (std::nothrow) NullDisplay;
  if (display == nullptr) {
    set_error(err, "out of memory", "");
    return nullptr;
  }
  display->verbose = verbose;
  return reinterpret_cast<mhd_plugin_instance*>(display);
}

mhd_status display_start(mhd_plugin_instance* /*self*/, mhd_error* /*err*/) { return MHD_OK; }

mhd_status display_stop(mhd_plugin_instance* self, mhd_error* /*err*/) {
  const NullDisplay* display = self_of(self);
  if (display->verbose) std::fprintf(stderr, "null_display: %llu frames\n", display->frames);
  return MHD_OK;
}

void display_close(mhd_plugin_instance* self) { delete self_of(self); }

mhd_status display_write(mhd_plugin_instance* self, const mhd_display_frame* /*frame*/, mhd_error* /*err*/) {
  ++self_of(self)->frames;
  return MHD_OK;
}

// The host checks a scene's parameters against this before open() (mhd validate too).
const mhd_param_decl kParams[] = {
    {"verbose", MHD_PARAM_BOOL, "", 0u, 0.0, 0.0, nullptr, "false", "print the frame count to stderr on stop"},
};

mhd_plugin_api make_api() {
  mhd_plugin_api api{};  // every call this plugin does not provide stays NULL
  api.abi_version = MHD_PLUGIN_ABI_VERSION;
  api.struct_size = sizeof(mhd_plugin_api);
  api.kind = MHD_KIND_DISPLAY;
  api.name = "null_display";  // must match the file name: libmhd_null_display.so
  api.version = "1.0.0";
  api.description = "Draws nothing; counts frames (verbose=true prints the count on stop)";
  api.open = display_open;
  api.start = display_start;
  api.stop = display_stop;
  api.close = display_close;
  api.params = kParams;
  api.param_count = sizeof(kParams) / sizeof(kParams[0]);
  api.display_write = display_write;
  return api;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;  // a host we were not built for
  static const mhd_plugin_api api = make_api();
  return &api;
}
