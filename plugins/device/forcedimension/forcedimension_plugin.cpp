// forcedimension: Force Dimension's omega, sigma and delta devices and the Novint Falcon
// through the Force Dimension SDK (libdhd), loaded when the plugin opens. The SDK's calls
// are synchronous: device_read and device_write make them on MHD's haptic thread, as
// CHAI3D does, with no lock. The device's firmware watchdog is armed at start. Device
// frame D is the SDK's (x towards the user, y to the right, z up), in metres.
#include "dhd_runtime.h"

#include <mhd/plugin_sdk.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace mhd_forcedimension {
namespace {

/// device_read asks the device whether its forces are on every this many reads (64 ms).
constexpr unsigned kStatusEveryReads = 64;

bool all_finite(const std::array<double, 3>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

}  // namespace

class ForceDimension {
 public:
  static constexpr std::array kParams{
      mhd::sdk::text("library", "libdhd.so", "the Force Dimension SDK's library (a name the loader finds, or a path)"),
      mhd::sdk::number("command_timeout_s", "s", "0.01",
                       "the device's firmware watchdog: no force within this time, forces off",
                       mhd::sdk::between(0.001, 0.03)),
      mhd::sdk::integer("serial", "", "0", "the device's serial number; 0 for the first device found",
                        mhd::sdk::between(0, 65535)),
      mhd::sdk::number("force_limit_N", "N", "100",
                       "the most force MHD sends; the device's nominal maximum when that is lower",
                       mhd::sdk::between(0.1, 100)),
  };

  ForceDimension(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host), runtime_(load_dhd(params.text("library"))), dhd_(runtime_->calls()),
        watchdog_ticks_(static_cast<unsigned char>(
            std::lround(params.number("command_timeout_s") / dhd::kWatchdogTickS))) {
    const auto serial = params.integer("serial");
    id_ = serial == 0 ? dhd_.dhdOpen() : dhd_.dhdOpenSerial(static_cast<int>(serial));
    if (id_ < 0) throw std::runtime_error(describe_last_error(dhd_, serial == 0 ? "dhdOpen" : "dhdOpenSerial"));
    try {
      const int type = dhd_.dhdGetSystemType(device());
      if (type < 0) throw std::runtime_error(describe_last_error(dhd_, "dhdGetSystemType"));
      model_ = model_of(type);
      if (model_ == nullptr) {
        const char* name = dhd_.dhdGetSystemName(device());
        throw std::runtime_error("the Force Dimension device '" + std::string(name != nullptr ? name : "?") +
                                 "' (type " + std::to_string(type) + ") is not one MHD knows the limits of");
      }
      fill_info(params.number("force_limit_N"));
    } catch (...) {
      dhd_.dhdClose(device());
      throw;
    }
  }
  ForceDimension(const ForceDimension&) = delete;
  ForceDimension& operator=(const ForceDimension&) = delete;
  ~ForceDimension() {
    dhd_.dhdStop(device());  // forces off, brakes on
    dhd_.dhdClose(device());
  }

  /// The firmware watchdog before force output (plugin_abi.h, "Ending safely").
  void start() {
    if (dhd_.dhdSetWatchdog(watchdog_ticks_, device()) < 0) {
      throw std::runtime_error(describe_last_error(dhd_, "dhdSetWatchdog") +
                               " (MHD drives a device only with its firmware watchdog armed)");
    }
    check(dhd_.dhdSetGravityCompensation(dhd::kOn, device()), "dhdSetGravityCompensation");
    check(dhd_.dhdSetForce(0.0, 0.0, 0.0, device()), "dhdSetForce");
    check(dhd_.dhdEnableForce(dhd::kOn, device()), "dhdEnableForce");
  }

  /// Zero force, then force output off.
  void stop() {
    const int zero = dhd_.dhdSetForce(0.0, 0.0, 0.0, device());
    const int off = dhd_.dhdEnableForce(dhd::kOff, device());
    check(zero, "dhdSetForce");
    check(off, "dhdEnableForce");
  }

  void device_info(mhd_device_info& out) const { out = info_; }

  void device_read(mhd_device_state& out) {
    std::array<double, 3> p_D_m{};
    std::array<double, 3> v_D_mps{};
    check(dhd_.dhdGetPosition(&p_D_m[0], &p_D_m[1], &p_D_m[2], device()), "dhdGetPosition");
    check(dhd_.dhdGetLinearVelocity(&v_D_mps[0], &v_D_mps[1], &v_D_mps[2], device()), "dhdGetLinearVelocity");
    if (!all_finite(p_D_m) || !all_finite(v_D_mps)) {
      throw std::runtime_error("the SDK returned a non-finite tool position or velocity");
    }
    out = mhd_device_state{};
    out.timestamp_s = mhd::sdk::host_now(host_);
    for (std::size_t i = 0; i < 3; ++i) {
      out.p_D_tool_m[i] = p_D_m[i];
      out.v_D_tool_mps[i] = v_D_mps[i];
    }
    out.q_D_tool_wxyz[0] = 1.0;  // the translation only
    out.buttons = dhd_.dhdGetButtonMask(device());
    if (++reads_ % kStatusEveryReads == 0) check_forces_on();
  }

  // The host has clamped the force to max_force_N. A saturated motor or the SDK's time
  // guard skipping a call is not an error.
  void device_write(const mhd_device_command& command) {
    check(dhd_.dhdSetForce(command.force_D_N[0], command.force_D_N[1], command.force_D_N[2], device()),
          "dhdSetForce");
  }

 private:
  [[nodiscard]] char device() const noexcept { return static_cast<char>(id_); }

  void check(int result, const char* call) const {
    if (result < 0) throw std::runtime_error(describe_last_error(dhd_, call));
  }

  /// The device turns its forces off by itself (its watchdog, a button, a velocity
  /// threshold, a lost link): the run ends with the cause rather than rendering nothing.
  void check_forces_on() const {
    std::array<int, dhd::kStatusCount> status{};
    check(dhd_.dhdGetStatus(status.data(), device()), "dhdGetStatus");
    if (status[dhd::kStatusForce] == 0) {
      throw std::runtime_error(std::string("the device turned its forces off: ") +
                               force_off_cause(status[dhd::kStatusForceOffCause]));
    }
  }

  void fill_info(double force_limit_N) {
    info_ = mhd_device_info{};
    info_.max_force_N = std::min(model_->max_force_N, force_limit_N);
    info_.max_stiffness_N_per_m = model_->max_stiffness_N_per_m;
    info_.dof_in = 3;
    info_.dof_out = 3;
    info_.workspace_box_count = 1;
    for (std::size_t i = 0; i < 3; ++i) {
      info_.workspace[0].min_m[i] = -model_->half_width_m[i];
      info_.workspace[0].max_m[i] = model_->half_width_m[i];
    }
  }

  mhd_host host_;
  std::unique_ptr<DhdRuntime> runtime_;
  const DhdCalls& dhd_;
  unsigned char watchdog_ticks_;
  int id_ = -1;
  const DeviceModel* model_ = nullptr;
  mhd_device_info info_{};
  unsigned reads_ = 0;
};

}  // namespace mhd_forcedimension

MHD_PLUGIN_ENTRY(mhd_forcedimension::ForceDimension,
                 {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Force Dimension omega, sigma, delta and Novint Falcon through the DHD SDK (libdhd)"})
