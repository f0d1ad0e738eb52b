// vendor_cartesian: a device plugin over a Cartesian vendor SDK (vendor_sdk.h, here a
// simulated stand-in). The vendor speaks millimetres, MHD speaks metres: the plugin converts.
#include "vendor_sdk.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <stdexcept>
#include <string>

namespace vendor_cartesian {

constexpr double kMmPerM = 1000.0;

/// A failed vendor call becomes an exception, which the SDK turns into MHD_ERROR.
inline void check(int code, const char* call) {
  if (code != VC_OK) throw std::runtime_error(std::string(call) + ": " + vc_error_string(code));
}

class VendorCartesian {
 public:
  static constexpr std::array kParams{
      mhd::sdk::text("serial", "SIM-0001", "the device's serial number"),
      mhd::sdk::number("watchdog_s", "s", "0.01", "the device's own command timeout", mhd::sdk::between(0.001, 1)),
  };

  VendorCartesian(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host), watchdog_ms_(static_cast<unsigned>(params.number("watchdog_s") * 1000.0)) {
    check(vc_open(params.text("serial").c_str(), &device_), "vc_open");
  }
  VendorCartesian(const VendorCartesian&) = delete;
  VendorCartesian& operator=(const VendorCartesian&) = delete;
  ~VendorCartesian() { vc_close(device_); }

  // The hardware's own watchdog before motor power (plugin_abi.h, "Ending safely").
  void start() {
    check(vc_set_watchdog_ms(device_, watchdog_ms_), "vc_set_watchdog_ms");
    check(vc_enable_forces(device_, 1), "vc_enable_forces");
  }
  void stop() { check(vc_enable_forces(device_, 0), "vc_enable_forces"); }

  void device_info(mhd_device_info& out) const {
    double min_mm[3];
    double max_mm[3];
    check(vc_get_workspace_mm(device_, min_mm, max_mm), "vc_get_workspace_mm");
    out = mhd_device_info{};
    out.max_force_N = vc_max_force_N(device_);
    out.max_stiffness_N_per_m = vc_max_stiffness_N_per_mm(device_) * kMmPerM;
    out.dof_in = 3;
    out.dof_out = 3;
    out.workspace_box_count = 1;
    for (int i = 0; i < 3; ++i) {
      out.workspace[0].min_m[i] = min_mm[i] / kMmPerM;
      out.workspace[0].max_m[i] = max_mm[i] / kMmPerM;
    }
  }

  void device_read(mhd_device_state& out) {
    double p_D_mm[3];
    double v_D_mm_s[3];
    check(vc_get_position_mm(device_, p_D_mm), "vc_get_position_mm");
    check(vc_get_velocity_mm_s(device_, v_D_mm_s), "vc_get_velocity_mm_s");
    out = mhd_device_state{};
    out.timestamp_s = mhd::sdk::host_now(host_);
    for (int i = 0; i < 3; ++i) {
      out.p_D_tool_m[i] = p_D_mm[i] / kMmPerM;
      out.v_D_tool_mps[i] = v_D_mm_s[i] / kMmPerM;
    }
    out.q_D_tool_wxyz[0] = 1.0;  // 3 input DOF: no orientation
    out.buttons = vc_get_buttons(device_);
  }

  // Newtons both sides; the host has already clamped the force to max_force_N.
  void device_write(const mhd_device_command& command) {
    check(vc_set_force_N(device_, command.force_D_N), "vc_set_force_N");
  }

 private:
  mhd_host host_;
  unsigned watchdog_ms_;
  vc_device* device_ = nullptr;
};

}  // namespace vendor_cartesian

MHD_PLUGIN_ENTRY(vendor_cartesian::VendorCartesian,
                 {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Example: a Cartesian vendor SDK (simulated stand-in), millimetres to metres"})
