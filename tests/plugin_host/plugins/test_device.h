#pragma once
// A small, valid device plugin (an SDK class) that each test plugin starts from and
// breaks in one way.
// Params (each optional and declared, so the host checks them; any other name is refused):
//   tool_x_m=<double>  p_D_tool_m[0] returned by device_read (default 0.05)
//   max_force_N=<double>  the device_info force limit (default 8.5)
//   read_status=ok|no_data|deactivate|error|bogus  what device_read returns
//   fail=start|stop  that call returns MHD_ERROR
// device_read reports the host clock in timestamp_s, the last written force in
// v_D_tool_mps and the number of reads so far in buttons. Lifecycle calls are appended to
// call_log ("open start stop close "), which good_device exports for the tests.

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

namespace test_device {

inline char call_log[256] = {};

inline void log_call(const char* call) {
  std::strncat(call_log, call, sizeof(call_log) - std::strlen(call_log) - 1);
  std::strncat(call_log, " ", sizeof(call_log) - std::strlen(call_log) - 1);
}

/// What the parameters ask of the device.
struct Settings {
  double tool_x_m = 0.05;
  double max_force_N = 8.5;
  int read_status = MHD_OK;
  bool fail_start = false;
  bool fail_stop = false;
};

class Device {
 public:
  static constexpr std::array kParams{
      mhd::sdk::number("tool_x_m", "m", "0.05", "p_D_tool_m[0] that device_read returns"),
      mhd::sdk::number("max_force_N", "N", "8.5", "the force limit device_info reports"),
      mhd::sdk::choice("read_status", "ok|no_data|deactivate|error|bogus", "ok", "what device_read returns"),
      mhd::sdk::choice("fail", "start|stop", nullptr, "that call returns MHD_ERROR"),
  };

  Device(const mhd_host& host, const mhd::sdk::Params& params) : Device(host, settings_from(params)) {}
  Device(const mhd_host& host, const Settings& settings) : host_(host), settings_(settings) { log_call("open"); }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  ~Device() { log_call("close"); }

  void start() {
    log_call("start");
    if (settings_.fail_start) throw std::runtime_error("motors not powered");
  }
  void stop() {
    log_call("stop");
    if (settings_.fail_stop) throw std::runtime_error("brake did not engage");
  }

  void device_info(mhd_device_info& out) const {
    out = mhd_device_info{};
    out.max_force_N = settings_.max_force_N;
    out.max_stiffness_N_per_m = 2000.0;
    out.dof_in = 3;
    out.dof_out = 3;
    out.workspace_box_count = 1;
    for (int i = 0; i < 3; ++i) {
      out.workspace[0].min_m[i] = -0.1;
      out.workspace[0].max_m[i] = 0.1;
    }
  }

  mhd_status device_read(mhd_device_state& out) {
    ++reads_;
    if (settings_.read_status == MHD_ERROR) throw std::runtime_error("encoder cable unplugged");
    out.timestamp_s = host_.now_s(host_.clock_context);
    out.p_D_tool_m[0] = settings_.tool_x_m;
    out.p_D_tool_m[1] = 0.02;
    out.p_D_tool_m[2] = -0.02;
    for (int i = 0; i < 3; ++i) out.v_D_tool_mps[i] = last_force_N_[i];
    out.q_D_tool_wxyz[0] = 1.0;
    out.q_D_tool_wxyz[1] = out.q_D_tool_wxyz[2] = out.q_D_tool_wxyz[3] = 0.0;
    out.buttons = reads_;
    // A C plugin may return any int; the host must cope (7 is no mhd_status).
    return static_cast<mhd_status>(settings_.read_status);
  }

  void device_write(const mhd_device_command& command) {
    for (int i = 0; i < 3; ++i) last_force_N_[i] = command.force_D_N[i];
  }

  void simulate_until(double /*t_s*/) {}

 private:
  static Settings settings_from(const mhd::sdk::Params& params) {
    Settings s;
    s.tool_x_m = params.number("tool_x_m");
    s.max_force_N = params.number("max_force_N");
    const std::string status = params.text("read_status");
    s.read_status = status == "no_data"      ? MHD_NO_DATA
                    : status == "deactivate" ? MHD_DEACTIVATE
                    : status == "error"      ? MHD_ERROR
                    : status == "bogus"      ? 7
                                             : MHD_OK;
    const std::string fail = params.optional_text("fail").value_or("");
    s.fail_start = fail == "start";
    s.fail_stop = fail == "stop";
    return s;
  }

  mhd_host host_;
  Settings settings_;
  double last_force_N_[3] = {0.0, 0.0, 0.0};
  unsigned reads_ = 0;
};

namespace {  // internal: a vague-linkage object would be a GNU unique symbol, never unloaded
constexpr mhd::sdk::PluginInfo kInfo{
    .kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.2.3", .description = "test device"};
}  // namespace

/// The full, valid table (name from mhd_add_plugin's MHD_PLUGIN_NAME), for the plugins
/// that break one entry of it.
inline mhd_plugin_api make_api() { return mhd::sdk::plugin_table<Device, kInfo>(); }

namespace {
/// What a plugin with a broken table returns from mhd_plugin_entry, whatever the host:
/// make_api() with `breaks` applied (a table the host must refuse), built once.
template <class Break>
const mhd_plugin_api* broken_table(Break breaks) {
  static const mhd_plugin_api api = [&] {
    mhd_plugin_api a = make_api();
    breaks(a);
    return a;
  }();
  return &api;
}
}  // namespace

}  // namespace test_device
