// The sim_omni3 base plugin: the C ABI over Omni3Model. Commands are stamped with the
// host clock when they arrive; the host advances the base with simulate_until(), and
// the true pose goes to the shared simulated world after every advance. With command_log,
// every command and every firing of the command watchdog goes to a CSV
// (sim_common/command_log.h).

#include "sim_omni3_model.h"
#include "sim_common/command_log.h"
#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <atomic>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace mhd::sim_omni3 {
namespace {

using plugin_support::guarded_open;

constexpr double kDegToRad = std::numbers::pi / 180.0;

struct Config {
  Omni3Config model;
  std::string command_log;  ///< empty: none
};

struct Instance {
  Instance(const mhd_host& h, const Config& config) : host(h), model(config.model) {
    if (!config.command_log.empty()) {
      log = std::make_unique<plugin_support::CommandLog>(config.command_log,
                                                         std::array{"vx_mps", "vz_mps", "omega_radps"});
    }
  }

  std::atomic<bool> in_call{false};  ///< plugin_support::with_instance's
  mhd_host host;
  Omni3Model model;
  bool started = false;
  bool read_once = false;
  double last_read_time_s = 0.0;
  std::unique_ptr<plugin_support::CommandLog> log;  ///< written inside with_instance only: one producer

  void log_event(double t_s, plugin_support::CommandEvent event, const std::array<double, 3>& values = {}) noexcept {
    if (log) log->add(t_s, event, values);
  }

  void publish_pose() {
    if (host.sim_world == nullptr) return;
    const PlanarPose& p = model.pose();
    host.sim_world->set_base_pose(host.sim_world->context, p.x_m, p.z_m, p.heading_rad);
  }
};

constexpr std::array kParams{
    sdk::number("base_radius_m", "m", "0.2", "from the centre to each wheel", sdk::positive()),
    sdk::number("wheel_radius_m", "m", "0.04", "each omni wheel's radius", sdk::positive()),
    sdk::number("max_speed_mps", "m/s", "0.5", "the fastest the base drives", sdk::positive()),
    sdk::number("max_omega_degps", "deg/s", "40", "the fastest it turns", sdk::positive()),
    sdk::number("control_rate_hz", "Hz", "50", "the motor controller's rate", sdk::positive()),
    sdk::number("motor_time_constant_s", "s", "0.05", "first-order lag of each wheel's speed", sdk::non_negative()),
    sdk::number("max_wheel_accel_mps2", "m/s^2", "1", "each wheel's acceleration limit", sdk::positive()),
    sdk::number("slip_fraction", "", "0", "wheel slip, a fraction of the commanded motion", sdk::fraction()),
    sdk::number("command_timeout_s", "s", "0.2", "the controller's own watchdog: stops without a fresh command",
                sdk::positive()),
    sdk::integer("seed", "", "0", "slip noise seed"),
    sdk::number("x_m", "m", nullptr, "start position x, world (default: the simulated world's base)"),
    sdk::number("z_m", "m", nullptr, "start position z, world (default: the simulated world's base)"),
    sdk::number("heading_deg", "deg", nullptr, "start heading (default: the simulated world's base)"),
    sdk::text("command_log", nullptr, "a CSV file that receives every command and watchdog firing"),
};

Config read_config(const mhd_host& host, const mhd_param* params, std::size_t count) {
  plugin_support::ParamReader reader(kParams, params, count);
  Config config;
  Omni3Config& c = config.model;
  c.base_radius_m = reader.positive("base_radius_m", c.base_radius_m);
  c.wheel_radius_m = reader.positive("wheel_radius_m", c.wheel_radius_m);
  c.max_speed_mps = reader.positive("max_speed_mps", c.max_speed_mps);
  c.max_omega_radps = reader.positive("max_omega_degps", c.max_omega_radps / kDegToRad) * kDegToRad;
  c.control_rate_hz = reader.positive("control_rate_hz", c.control_rate_hz);
  c.motor_time_constant_s = reader.non_negative("motor_time_constant_s", c.motor_time_constant_s);
  c.max_wheel_accel_mps2 = reader.positive("max_wheel_accel_mps2", c.max_wheel_accel_mps2);
  c.slip_fraction = reader.fraction("slip_fraction", c.slip_fraction);
  c.command_timeout_s = reader.positive("command_timeout_s", c.command_timeout_s);
  c.seed = reader.unsigned_integer("seed", c.seed, UINT64_MAX);
  // The start pose: the simulated world's base pose when there is one, each field
  // overridden by its parameter.
  PlanarPose& p = c.initial_pose;
  if (host.sim_world != nullptr) host.sim_world->get_base_pose(host.sim_world->context, &p.x_m, &p.z_m, &p.heading_rad);
  p.x_m = reader.number("x_m", p.x_m);
  p.z_m = reader.number("z_m", p.z_m);
  if (const auto heading_deg = reader.optional_number("heading_deg")) p.heading_rad = *heading_deg * kDegToRad;
  config.command_log = reader.optional_text("command_log").value_or("");
  reader.reject_unknown();
  return config;
}

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err) {
  return guarded_open(err, [&] {
    plugin_support::check_host(host);
    plugin_support::check_sim_world(*host);
    auto* instance = new Instance(*host, read_config(*host, params, param_count));
    return reinterpret_cast<mhd_plugin_instance*>(instance);
  });
}

// Every instance call: find, lock and (for Need::Running) check the instance.
template <class F>
mhd_status call(mhd_plugin_instance* self, plugin_support::Need need, mhd_error* err, F&& f) {
  return plugin_support::with_instance<Instance>(MHD_PLUGIN_NAME, self, need, err, std::forward<F>(f));
}

mhd_status start_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    const double now = plugin_support::host_now(s.host);
    s.model.start(now);
    s.started = true;
    s.read_once = false;
    s.log_event(now, plugin_support::CommandEvent::Start);
    s.publish_pose();
    return MHD_OK;
  });
}

mhd_status stop_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    if (s.started) s.log_event(plugin_support::host_now(s.host), plugin_support::CommandEvent::Stop);
    s.started = false;  // the base stands where it is; start() begins again from here
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) { delete reinterpret_cast<Instance*>(self); }

mhd_status base_read(mhd_plugin_instance* self, mhd_base_state* out, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (out == nullptr) throw std::invalid_argument("base_read: out is NULL");
    const double t = s.model.time_s();
    if (s.read_once && t == s.last_read_time_s) return MHD_NO_DATA;
    const PlanarPose& p = s.model.pose();
    const Twist v_W = s.model.velocity_W();
    *out = mhd_base_state{t, p.x_m, p.z_m, p.heading_rad, v_W[0], v_W[1], v_W[2]};
    s.read_once = true;
    s.last_read_time_s = t;
    return MHD_OK;
  });
}

mhd_status base_write(mhd_plugin_instance* self, const mhd_base_command* command, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (command == nullptr) throw std::invalid_argument("base_write: command is NULL");
    const double now = plugin_support::host_now(s.host);
    s.model.command(Twist(command->vx_mps, command->vz_mps, command->omega_radps), now);
    s.log_event(now, plugin_support::CommandEvent::Command, {command->vx_mps, command->vz_mps, command->omega_radps});
    return MHD_OK;
  });
}

mhd_status simulate_until(mhd_plugin_instance* self, double t_s, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    const bool was_commanded = !s.model.watchdog_stopped();
    s.model.simulate_until(t_s);
    if (was_commanded && s.model.watchdog_stopped()) {
      // The base's own watchdog fired: the last command expired command_timeout_s after it came.
      s.log_event(s.model.command_time_s() + s.model.config().command_timeout_s, plugin_support::CommandEvent::Timeout);
    }
    s.publish_pose();
    return MHD_OK;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,
    .version = "1.0.0",
    .description = "Simulated three-omni-wheel base: 50 Hz wheel-speed control, limits, watchdog, optional slip",
    .open = open_instance,
    .start = start_instance,
    .stop = stop_instance,
    .close = close_instance,
    .params = kParams.data(),
    .param_count = kParams.size(),
    .device_info = nullptr,
    .device_read = nullptr,
    .device_write = nullptr,
    .tracker_read = nullptr,
    .base_read = base_read,
    .base_write = base_write,
    .display_write = nullptr,
    .simulate_until = simulate_until,
    .tracker_wait = nullptr,
    .counters = nullptr,
};

}  // namespace
}  // namespace mhd::sim_omni3

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::sim_omni3::kApi : nullptr;
}
