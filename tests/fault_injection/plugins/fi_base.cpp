// A base for the fault-injection suite: moves the scene's simulated base (sim_world/sim_session.h) with the twist it
// was last commanded (integrated at every base_read, no dynamics), so the tracker sees
// the base that is commanded; logs every command with its time; fails on cue.
// Parameters:
//   fault=none|nan|error|deactivate, fault_after_s (never), fault_on=read|write (read)
//     nan: base_read returns a NaN x_m; error: MHD_ERROR with a message
//   command_log=<path>  at close, one line per base_write: "t_s vx_mps vz_mps omega_radps",
//                       and a marker "t_s nan nan nan" when the fault strikes
#include "probe_common.h"
#include "sim_world/sim_session.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace {

class FiBase {
 public:
  static constexpr auto kParams = probe::kFaultParams;

  FiBase(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host), session_(mhd::sim_world::SimSession::acquire(host)), fault_(params, 1u << 20) {}

  void start() {
    last_read_s_ = mhd::sdk::host_now(host_);
    fault_.start(last_read_s_);
  }

  mhd_status base_read(mhd_base_state& out) {
    const double t_s = mhd::sdk::host_now(host_);
    mhd::simulation::SimulatedWorld& w = session_->world();
    const mhd::simulation::PlanarPose pose = w.base_pose();
    double x = pose.x_m, z = pose.z_m, h = pose.heading_rad;
    // Base frame: x forward = (cos h, 0, -sin h), z = x cross y = (sin h, 0, cos h).
    const double dt = t_s - last_read_s_;
    last_read_s_ = t_s;
    const double vx_W = last_.vx_mps * std::cos(h) + last_.vz_mps * std::sin(h);
    const double vz_W = -last_.vx_mps * std::sin(h) + last_.vz_mps * std::cos(h);
    x += vx_W * dt;
    z += vz_W * dt;
    h += last_.omega_radps * dt;
    w.set_base_pose({x, z, h});
    out = {.timestamp_s = t_s, .x_m = x, .z_m = z, .heading_rad = h, .vx_mps = vx_W, .vz_mps = vz_W,
           .omega_radps = last_.omega_radps, .has_lift = 0, .lift_m = 0.0, .lift_vmps = 0.0};
    bool nan = false;
    const mhd_status status =
        fault_.on(probe::FaultOn::Read, t_s, "injected fault: base controller not responding", nan);
    if (nan) out.x_m = std::numeric_limits<double>::quiet_NaN();
    return status;
  }

  mhd_status base_write(const mhd_base_command& c) {
    fault_.commands.add(c.timestamp_s, c.vx_mps, c.vz_mps, c.omega_radps);
    last_ = c;
    bool nan = false;
    return fault_.on(probe::FaultOn::Write, mhd::sdk::host_now(host_), "injected fault: base controller not responding",
                     nan);
  }

 private:
  mhd_host host_;
  std::shared_ptr<mhd::sim_world::SimSession> session_;
  probe::FaultOnCue fault_;
  double last_read_s_ = 0.0;
  mhd_base_command last_{};
};

}  // namespace

MHD_PLUGIN_ENTRY(FiBase, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                          .description = "test base: moves the simulated base, logs every command, fails on cue"})
