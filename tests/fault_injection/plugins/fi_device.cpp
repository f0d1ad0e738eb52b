// A Cartesian device for the fault-injection suite: its tool follows a script (held at
// p_free_m, then moved to p_press_m over press_ramp_s from press_at_s, device frame, so a test
// places a surface between the two HIPs and the device presses into it), it logs every
// command with its time, and it fails on cue.
// Parameters:
//   p_free_m, p_press_m   "x y z" (default: a PHANToM's tool at joint angles 0 0.3 0.2)
//   press_at_s (never), press_ramp_s (0.05)   seconds after start
//   max_force_N (8.5)     the force limit device_info reports
//   workspace_min_m, workspace_max_m   the one workspace box device_info reports (default a PHANToM's)
//   fault=none|nan|error|deactivate, fault_after_s (never), fault_on=read|write (read)
//     nan: p_D_tool_m[1] is NaN (read only); error: MHD_ERROR with a message
//   command_log=<path>  at close, one line per device_write: "t_s fx fy fz" (N, device frame), and
//                       a marker "t_s nan nan nan" when the fault strikes
#include "probe_common.h"

#include "phantom_like_device_info.h"

#include <algorithm>
#include <array>
#include <limits>

namespace {

using Vec3 = std::array<double, 3>;

class FiDevice {
 public:
  static constexpr auto kParams = mhd::sdk::join(
      std::array{
          mhd::sdk::vector3("p_free_m", "m", nullptr, "the tool before the press (default: mid-workspace)"),
          mhd::sdk::vector3("p_press_m", "m", nullptr, "the tool pressing (default: mid-workspace)"),
          mhd::sdk::number("press_at_s", "s", nullptr, "when the press starts, after start (absent: never)"),
          mhd::sdk::number("press_ramp_s", "s", "0.05", "how long it takes", mhd::sdk::non_negative()),
          mhd::sdk::number("max_force_N", "N", nullptr, "the force limit device_info reports (default a PHANToM's)",
                           mhd::sdk::positive()),
          mhd::sdk::vector3("workspace_min_m", "m", nullptr, "the workspace box's low corner (default a PHANToM's)"),
          mhd::sdk::vector3("workspace_max_m", "m", nullptr, "the workspace box's high corner (default a PHANToM's)"),
      },
      probe::kFaultParams);

  FiDevice(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host),
        p_free_(params.optional_vector3<Vec3>("p_free_m").value_or(test_plugins::kPhantomMidTool_D_m)),
        p_press_(params.optional_vector3<Vec3>("p_press_m").value_or(test_plugins::kPhantomMidTool_D_m)),
        press_at_s_(params.optional_number("press_at_s").value_or(std::numeric_limits<double>::infinity())),
        press_ramp_s_(params.number("press_ramp_s")),
        max_force_N_(params.optional_number("max_force_N").value_or(test_plugins::kPhantomMaxForce_N)),
        info_(workspace_info(params)),
        fault_(params, 1u << 17) {}  // 131 s at 1 kHz

  void start() { fault_.start(t_start_s_ = mhd::sdk::host_now(host_)); }
  void device_info(mhd_device_info& out) {
    out = info_;
    out.max_force_N = max_force_N_;
  }

  mhd_status device_read(mhd_device_state& out) {
    const double t_s = mhd::sdk::host_now(host_);
    out = {};
    out.timestamp_s = t_s;
    const double since_s = t_s - t_start_s_ - press_at_s_;
    const double s = press_ramp_s_ > 0.0 ? std::clamp(since_s / press_ramp_s_, 0.0, 1.0) : (since_s >= 0.0 ? 1.0 : 0.0);
    for (std::size_t i = 0; i < 3; ++i) out.p_D_tool_m[i] = p_free_[i] + s * (p_press_[i] - p_free_[i]);
    out.q_D_tool_wxyz[0] = 1.0;
    bool nan = false;
    const mhd_status status = fault_.on(probe::FaultOn::Read, t_s, "injected fault: encoder read failed", nan);
    if (nan) out.p_D_tool_m[1] = std::numeric_limits<double>::quiet_NaN();
    return status;
  }

  mhd_status device_write(const mhd_device_command& c) {
    fault_.commands.add(c.timestamp_s, c.force_D_N[0], c.force_D_N[1], c.force_D_N[2]);
    bool nan = false;
    return fault_.on(probe::FaultOn::Write, mhd::sdk::host_now(host_), "injected fault: amplifier not responding", nan);
  }

 private:
  mhd_host host_;
  Vec3 p_free_, p_press_;
  double press_at_s_, press_ramp_s_, max_force_N_;
  mhd_device_info info_;
  double t_start_s_ = 0.0;

  static mhd_device_info workspace_info(const mhd::sdk::Params& params) {
    mhd_device_info info = test_plugins::phantom_like_device_info();
    const Vec3 min_m = params.optional_vector3<Vec3>("workspace_min_m").value_or(Vec3{info.workspace[0].min_m[0], info.workspace[0].min_m[1],
                                                                 info.workspace[0].min_m[2]});
    const Vec3 max_m = params.optional_vector3<Vec3>("workspace_max_m").value_or(Vec3{info.workspace[0].max_m[0], info.workspace[0].max_m[1],
                                                                 info.workspace[0].max_m[2]});
    for (std::size_t i = 0; i < 3; ++i) {
      info.workspace[0].min_m[i] = min_m[i];
      info.workspace[0].max_m[i] = max_m[i];
    }
    return info;
  }
  probe::FaultOnCue fault_;
};

}  // namespace

MHD_PLUGIN_ENTRY(FiDevice, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                            .description = "test device: scripted tool path, logs every command, fails on cue"})
