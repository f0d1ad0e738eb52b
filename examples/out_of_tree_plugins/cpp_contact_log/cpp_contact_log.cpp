// cpp_contact_log: an MHD display plugin in C++17, built out of tree. From the frames the
// host gives it, it counts the contacts (a frame in contact after one that was not) and
// keeps the largest force magnitude; on stop it prints to stderr
//   cpp_contact_log: <N> frames, <C> contacts, max force <F> N
// Parameter: min_force_N (default 0): a contact counts only once the force reaches it.
// Includes only <mhd/plugin_abi.h> and the standard library.

#include <mhd/plugin_abi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

namespace {

constexpr const char* kName = "cpp_contact_log";  // mhd_add_plugin(NAME cpp_contact_log ...)

struct ContactLog {
  double min_force_N = 0.0;
  unsigned long long frames = 0;
  unsigned long long contacts = 0;
  bool touching = false;
  double max_force_N = 0.0;
};

ContactLog* self_of(mhd_plugin_instance* self) { return reinterpret_cast<ContactLog*>(self); }

bool parse_non_negative(const char* text, double* value) {
  char* end = nullptr;
  const double parsed = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(parsed) || parsed < 0.0) return false;
  *value = parsed;
  return true;
}

// Declared for the host, which checks a scene's parameters before open() (ABI 3).
const mhd_param_decl kParams[] = {
    {"min_force_N", MHD_PARAM_NUMBER, "N", MHD_PARAM_HAS_MIN, 0.0, 0.0, nullptr, "0",
     "a contact counts only once the force reaches this"},
};

mhd_plugin_instance* log_open(const mhd_host* /*host*/, const mhd_param* params, size_t param_count, mhd_error* err) {
  double min_force_N = 0.0;
  for (size_t i = 0; i < param_count; ++i) {
    if (std::strcmp(params[i].name, "min_force_N") != 0) {
      std::snprintf(err->message, sizeof(err->message), "unknown parameter '%s'", params[i].name);
      return nullptr;
    }
    if (!parse_non_negative(params[i].value, &min_force_N)) {
      std::snprintf(err->message, sizeof(err->message), "min_force_N must be a number >= 0, not '%s'",
                    params[i].value);
      return nullptr;
    }
  }
  auto* log = new (std::nothrow) ContactLog;
  if (log == nullptr) {
    std::snprintf(err->message, sizeof(err->message), "out of memory");
    return nullptr;
  }
  log->min_force_N = min_force_N;
  return reinterpret_cast<mhd_plugin_instance*>(log);
}

mhd_status log_start(mhd_plugin_instance* /*self*/, mhd_error* /*err*/) { return MHD_OK; }

mhd_status log_stop(mhd_plugin_instance* self, mhd_error* /*err*/) {
  const ContactLog* log = self_of(self);
  std::fprintf(stderr, "%s: %llu frames, %llu contacts, max force %.3f N\n", kName, log->frames, log->contacts,
               log->max_force_N);
  return MHD_OK;
}

void log_close(mhd_plugin_instance* self) { delete self_of(self); }

mhd_status log_write(mhd_plugin_instance* self, const mhd_display_frame* frame, mhd_error* /*err*/) {
  ContactLog* log = self_of(self);
  ++log->frames;
  const double force_N = std::sqrt(frame->force_W_N[0] * frame->force_W_N[0] + frame->force_W_N[1] * frame->force_W_N[1] +
                                   frame->force_W_N[2] * frame->force_W_N[2]);
  if (force_N > log->max_force_N) log->max_force_N = force_N;
  const bool touching = frame->in_contact != 0 && force_N >= log->min_force_N;
  if (touching && !log->touching) ++log->contacts;
  log->touching = touching;
  return MHD_OK;
}

mhd_plugin_api make_api() {
  mhd_plugin_api api{};  // every call left out stays NULL
  api.abi_version = MHD_PLUGIN_ABI_VERSION;
  api.struct_size = sizeof(mhd_plugin_api);
  api.kind = MHD_KIND_DISPLAY;
  api.name = kName;
  api.version = "1.0.0";
  api.description = "Counts contacts and the largest force (C++ example, built out of tree)";
  api.open = log_open;
  api.start = log_start;
  api.stop = log_stop;
  api.close = log_close;
  api.params = kParams;
  api.param_count = sizeof(kParams) / sizeof(kParams[0]);
  api.display_write = log_write;
  return api;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;  // a host we were not built for
  static const mhd_plugin_api api = make_api();
  return &api;
}
