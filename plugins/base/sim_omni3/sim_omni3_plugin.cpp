// The sim_omni3 base plugin: the C ABI over Omni3Model. Commands are stamped with the
// host clock when they arrive; the host advances the base with simulate_until(), and
// the true pose goes to the scene's simulated world (sim_world/sim_session.h) after every advance. With command_log,
// every command and every firing of the command watchdog goes to a CSV
// (sim_common/command_log.h). With lift=on the base carries a lift (lift_model.h), whose
// height goes to the simulated world as well.

#include "lift_model.h"
#include "sim_omni3_model.h"
#include "sim_common/command_log.h"
#include "sim_world/sim_session.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <numbers>
#include <utility>

namespace mhd::sim_omni3 {

using plugin_support::CommandEvent;

constexpr double kDegToRad = std::numbers::pi / 180.0;

class SimOmni3Plugin {
 public:
  static constexpr std::array kParams{
      sdk::number("base_radius_m", "m", "0.2", "from the centre to each wheel", sdk::between(0.01, 10)),
      sdk::number("wheel_radius_m", "m", "0.04", "each omni wheel's radius", sdk::between(0.001, 1)),
      sdk::number("max_speed_mps", "m/s", "0.5", "the fastest the base drives", sdk::between(0.001, 10)),
      sdk::number("max_omega_degps", "deg/s", "40", "the fastest it turns", sdk::between(0.01, 3600)),
      sdk::number("control_rate_hz", "Hz", "50", "the motor controller's rate", sdk::between(1, 1000)),
      sdk::number("motor_time_constant_s", "s", "0.05", "first-order lag of each wheel's speed", sdk::between(0, 10)),
      sdk::number("max_wheel_accel_mps2", "m/s^2", "1", "each wheel's acceleration limit", sdk::between(0.001, 100)),
      sdk::number("slip_fraction", "", "0", "wheel slip, a fraction of the commanded motion", sdk::fraction()),
      sdk::number("command_timeout_s", "s", "0.2", "the controller's own watchdog: stops without a fresh command",
                  sdk::between(0.001, 10)),
      sdk::integer("seed", "", "0", "slip noise seed", sdk::between(0, 4294967295.0)),
      sdk::number("x_m", "m", nullptr, "start position x, world (default: the simulated world's base)",
                  sdk::between(-1000, 1000)),
      sdk::number("z_m", "m", nullptr, "start position z, world (default: the simulated world's base)",
                  sdk::between(-1000, 1000)),
      sdk::number("heading_deg", "deg", nullptr, "start heading (default: the simulated world's base)",
                  sdk::between(-3600, 3600)),
      sdk::text("command_log", nullptr, "a CSV file that receives every command and watchdog firing"),
      sdk::choice("lift", "off|on", "off", "whether the base carries a lift (the rig's <lift>; lift_* below)"),
      sdk::number("lift_min_m", "m", "-0.5", "the lift's lower end stop, below the rig file's arm height",
                  sdk::between(-10, 0)),
      sdk::number("lift_max_m", "m", "0.5", "the lift's upper end stop, above the rig file's arm height",
                  sdk::between(0, 10)),
      sdk::number("lift_max_speed_mps", "m/s", "0.3", "the fastest the lift moves", sdk::between(0.001, 10)),
      sdk::number("lift_max_acceleration_mps2", "m/s^2", "1.5", "the lift's acceleration limit",
                  sdk::between(0.001, 100)),
      sdk::number("lift_start_m", "m", "0", "where the lift stands at open, within its stops", sdk::between(-10, 10)),
  };

  SimOmni3Plugin(const mhd_host& host, const sdk::Params& params)
      : host_(host),
        session_(sim_world::SimSession::acquire(host)),
        model_(read_config(*session_, params)),
        lift_(read_lift(params, model_.config().command_timeout_s)) {
    if (const auto file = params.optional_text("command_log")) {
      log_ = std::make_unique<plugin_support::CommandLog>(*file, std::array{"vx_mps", "vz_mps", "omega_radps", "lift_vmps"});
    }
  }

  void start() {
    const double now = sdk::host_now(host_);
    model_.start(now);
    if (lift_) lift_->start(now);
    read_once_ = false;
    log_event(now, CommandEvent::Start);
    publish_pose();
  }
  // The base stands where it is; start() begins again from here.
  void stop() { log_event(sdk::host_now(host_), CommandEvent::Stop); }

  mhd_status base_read(mhd_base_state& out) {
    const double t = model_.time_s();
    if (read_once_ && t == last_read_time_s_) return MHD_NO_DATA;
    const PlanarPose& p = model_.pose();
    const Twist v_W = model_.velocity_W();
    out = mhd_base_state{t, p.x_m, p.z_m, p.heading_rad, v_W[0], v_W[1], v_W[2], 0, 0.0, 0.0};
    if (lift_) {
      out.has_lift = 1;
      out.lift_m = lift_->height_m();
      out.lift_vmps = lift_->velocity_mps();
    }
    read_once_ = true;
    last_read_time_s_ = t;
    return MHD_OK;
  }

  void base_write(const mhd_base_command& command) {
    const double now = sdk::host_now(host_);
    // The base lives up to the command's arrival under the previous one: a controller tick
    // the host has not yet simulated saw that command, not this one, and a host frozen in
    // between let the watchdog fire in the gap.
    simulate_until(now);
    // Judged whole before any of it applies: a bad lift speed leaves the base's twist unchanged too.
    if (!std::isfinite(command.lift_vmps)) throw std::invalid_argument("base command has a non-finite value");
    model_.command(Twist(command.vx_mps, command.vz_mps, command.omega_radps), now);
    if (lift_) lift_->command(command.lift_vmps, now);
    log_event(now, CommandEvent::Command, {command.vx_mps, command.vz_mps, command.omega_radps}, command.lift_vmps);
  }

  void simulate_until(double t_s) {
    const bool was_commanded = !model_.watchdog_stopped();
    model_.simulate_until(t_s);
    if (lift_) lift_->simulate_until(t_s);
    // One command expires once: a second firing for the same command (the model re-armed
    // and stopped again by a tick on the command's deadline) is not a second event.
    if (was_commanded && model_.watchdog_stopped() && model_.command_time_s() != timed_out_command_s_) {
      timed_out_command_s_ = model_.command_time_s();
      // The base's own watchdog fired: the last command expired command_timeout_s after it came.
      log_event(model_.command_time_s() + model_.config().command_timeout_s, CommandEvent::Timeout);
    }
    publish_pose();
  }

 private:
  static Omni3Config read_config(sim_world::SimSession& session, const sdk::Params& params) {
    // The numbers that go to the model as they are (their ranges are declared above).
    constexpr std::array<std::pair<const char*, double Omni3Config::*>, 8> kPlainNumbers{{
        {"base_radius_m", &Omni3Config::base_radius_m},
        {"wheel_radius_m", &Omni3Config::wheel_radius_m},
        {"max_speed_mps", &Omni3Config::max_speed_mps},
        {"control_rate_hz", &Omni3Config::control_rate_hz},
        {"motor_time_constant_s", &Omni3Config::motor_time_constant_s},
        {"max_wheel_accel_mps2", &Omni3Config::max_wheel_accel_mps2},
        {"slip_fraction", &Omni3Config::slip_fraction},
        {"command_timeout_s", &Omni3Config::command_timeout_s},
    }};
    Omni3Config c;
    for (const auto& [name, field] : kPlainNumbers) c.*field = params.number(name);
    c.max_omega_radps = params.number("max_omega_degps") * kDegToRad;
    c.seed = params.integer("seed");
    // The start pose: the simulated world's base pose, each field overridden by its parameter.
    PlanarPose& p = c.initial_pose;
    const simulation::PlanarPose world_base = session.world().base_pose();
    p = {world_base.x_m, world_base.z_m, world_base.heading_rad};
    p.x_m = params.optional_number("x_m").value_or(p.x_m);
    p.z_m = params.optional_number("z_m").value_or(p.z_m);
    if (const auto heading_deg = params.optional_number("heading_deg")) p.heading_rad = *heading_deg * kDegToRad;
    return c;
  }

  static std::optional<LiftModel> read_lift(const sdk::Params& params, double command_timeout_s) {
    if (params.text("lift") != "on") return std::nullopt;
    LiftConfig c;
    c.min_m = params.number("lift_min_m");
    c.max_m = params.number("lift_max_m");
    c.max_speed_mps = params.number("lift_max_speed_mps");
    c.max_acceleration_mps2 = params.number("lift_max_acceleration_mps2");
    c.command_timeout_s = command_timeout_s;  // one controller, one watchdog
    c.initial_m = params.number("lift_start_m");
    return LiftModel(c);
  }

  void log_event(double t_s, CommandEvent event, const std::array<double, 3>& values = {},
                 double lift_vmps = 0.0) noexcept {
    if (log_) log_->add(t_s, event, std::array{values[0], values[1], values[2], lift_vmps});
  }

  void publish_pose() {
    const PlanarPose& p = model_.pose();
    session_->world().set_base_pose({p.x_m, p.z_m, p.heading_rad});
    if (lift_) session_->world().set_lift_m(lift_->height_m());
  }

  mhd_host host_;
  std::shared_ptr<sim_world::SimSession> session_;
  Omni3Model model_;
  std::optional<LiftModel> lift_;  ///< none unless lift=on
  bool read_once_ = false;
  double timed_out_command_s_ = -1.0;  ///< the command whose expiry was logged last
  double last_read_time_s_ = 0.0;
  std::unique_ptr<plugin_support::CommandLog> log_;  ///< written inside SDK calls only: one producer
};

}  // namespace mhd::sim_omni3

MHD_PLUGIN_ENTRY(mhd::sim_omni3::SimOmni3Plugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Simulated three-omni-wheel base: 50 Hz wheel-speed control, limits, watchdog, "
                                 "optional slip"})
