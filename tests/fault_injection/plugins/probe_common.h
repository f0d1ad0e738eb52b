#pragma once
// Shared by the fault-injection suite's test plugins (tests/fault_injection/plugins):
// reading <param>s, filling mhd_error, the host clock, the plugin table's lifecycle, and
// a preallocated log written to a file at close, so a test checks every command the
// "hardware" received, with its time, from the hardware's side.

#include <mhd/plugin_abi.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace probe {

inline void set_error(mhd_error* err, const std::string& text) {
  if (err != nullptr) std::snprintf(err->message, sizeof(err->message), "%s", text.c_str());
}

inline double now_s(const mhd_host& host) { return host.now_s(host.clock_context); }

/// A number parameter; throws std::invalid_argument naming the parameter when it does not parse.
inline double number(const std::string& name, const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || end == nullptr || *end != '\0') throw std::invalid_argument("parameter '" + name + "' is not a number: '" + value + "'");
  return v;
}

/// Three numbers separated by spaces.
inline void vector3(const std::string& name, const std::string& value, double out[3]) {
  char* p = const_cast<char*>(value.c_str());
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    out[i] = std::strtod(p, &end);
    if (end == p) throw std::invalid_argument("parameter '" + name + "' needs three numbers: '" + value + "'");
    p = end;
  }
  while (*p == ' ') ++p;
  if (*p != '\0') throw std::invalid_argument("parameter '" + name + "' needs three numbers: '" + value + "'");
}

/// What a fault plugin does once its fault time has come.
enum class Fault { None, Nan, Error, Deactivate };

inline Fault fault_from(const std::string& value) {
  if (value == "none") return Fault::None;
  if (value == "nan") return Fault::Nan;
  if (value == "error") return Fault::Error;
  if (value == "deactivate") return Fault::Deactivate;
  throw std::invalid_argument("bad fault '" + value + "' (none, nan, error, deactivate)");
}

/// Which call fails.
enum class FaultOn { Read, Write };

inline FaultOn fault_on_from(const std::string& value) {
  if (value == "read") return FaultOn::Read;
  if (value == "write") return FaultOn::Write;
  throw std::invalid_argument("bad fault_on '" + value + "' (read, write)");
}

/// Rows of four numbers (time and three values), kept in memory and written at close as
/// "%.9f %.17g %.17g %.17g" lines. Reserved at open: logging never allocates.
class Log {
 public:
  void open(std::string path, std::size_t capacity) {
    path_ = std::move(path);
    if (!path_.empty()) rows_.reserve(capacity);
  }
  void add(double t_s, double a, double b, double c) noexcept {
    if (path_.empty() || rows_.size() == rows_.capacity()) return;  // full: the rest is not kept
    rows_.push_back({t_s, a, b, c});
  }
  void write() const {
    if (path_.empty()) return;
    if (std::FILE* f = std::fopen(path_.c_str(), "w")) {
      for (const Row& r : rows_) std::fprintf(f, "%.9f %.17g %.17g %.17g\n", r.t, r.a, r.b, r.c);
      std::fclose(f);
    }
  }

 private:
  struct Row {
    double t, a, b, c;
  };
  std::string path_;
  std::vector<Row> rows_;
};

inline mhd_status no_op(mhd_plugin_instance*, mhd_error*) { return MHD_OK; }

/// A PHANToM Premium 1.5's device_info (its workspace box in the device frame).
inline mhd_status phantom_like_info(mhd_plugin_instance*, mhd_device_info* out, mhd_error*) {
  *out = mhd_device_info{};
  out->max_force_N = 8.5;
  out->max_stiffness_N_per_m = 3500.0;
  out->dof_in = 3;
  out->dof_out = 3;
  out->workspace_box_count = 1;
  const double lo[3] = {-0.1905, -0.0035, -0.1055}, hi[3] = {0.1905, 0.2635, 0.0855};
  for (int i = 0; i < 3; ++i) {
    out->workspace[0].min_m[i] = lo[i];
    out->workspace[0].max_m[i] = hi[i];
  }
  return MHD_OK;
}

/// The table every probe plugin starts from.
inline mhd_plugin_api table(const char* description) {
  mhd_plugin_api a{};
  a.abi_version = MHD_PLUGIN_ABI_VERSION;
  a.struct_size = sizeof(mhd_plugin_api);
  a.kind = MHD_PLUGIN_KIND;
  a.name = MHD_PLUGIN_NAME;
  a.version = "1.0.0";
  a.description = description;
  a.start = no_op;
  a.stop = no_op;
  return a;
}

/// open() with C++ exceptions kept on this side of the ABI: make() returns the instance.
template <class F>
mhd_plugin_instance* guarded_open(mhd_error* err, F&& make) noexcept {
  try {
    return reinterpret_cast<mhd_plugin_instance*>(make());
  } catch (const std::exception& e) {
    set_error(err, e.what());
  } catch (...) {
    set_error(err, "unknown exception");
  }
  return nullptr;
}

}  // namespace probe
