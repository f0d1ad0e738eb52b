// The sim_phantom device plugin: the C ABI over PhantomSimModel. A Cartesian device (ABI 3)
// as a vendor SDK is: it reports the tool point in its frame P, from the joint angles its
// encoders give (the thesis's forward kinematics), and maps the force it receives to motor
// torques itself, tau = J_P^T F (thesis ch. 5.2), clamped to its motors' limits. Torques are
// stamped with the host clock when they arrive; the host advances the device with simulate_until(),
// which reads the hand and the base pose from the simulated world (without a world: a
// fixed hand, parameter hand_P_m, in the device frame). hand_model selects the kinematic
// hand (a stiff spring) or the impedance hand (a mass-spring-damper pushed by the force). With command_log, every command
// and every firing of the command watchdog goes to a CSV (sim_common/command_log.h).
// docs/sim_phantom.md.

#include "sim_phantom_model.h"
#include "sim_common/command_log.h"
#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include "geometry/pose.h"

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

namespace mhd::sim_phantom {
namespace {

using plugin_support::guarded_open;

constexpr double kDegToRad = std::numbers::pi / 180.0;

struct Config {
  PhantomSimConfig model;
  Eigen::Vector3d rest_hand_P_m = Eigen::Vector3d::Zero();
  std::string command_log;  ///< empty: none
};

struct Instance {
  Instance(const mhd_host& h, const Config& config) : host(h), model(config.model), rest_hand_P_m(config.rest_hand_P_m) {
    if (!config.command_log.empty()) {
      log = std::make_unique<plugin_support::CommandLog>(config.command_log,
                                                         std::array{"force_x_N", "force_y_N", "force_z_N"});
    }
  }

  std::atomic<bool> in_call{false};  ///< plugin_support::with_instance's
  mhd_host host;
  PhantomSimModel model;
  Eigen::Vector3d rest_hand_P_m;
  bool started = false;
  bool read_once = false;
  double last_read_time_s = 0.0;
  Eigen::Vector3d last_read_p_P_m = Eigen::Vector3d::Zero();
  std::unique_ptr<plugin_support::CommandLog> log;  ///< written inside with_instance only: one producer

  void log_event(double t_s, plugin_support::CommandEvent event, const std::array<double, 3>& values = {}) noexcept {
    if (log) log->add(t_s, event, values);
  }

  /// Evaluates the device at t_s with the world's hand (where the user means it to be)
  /// and base pose, or without a world with the hand resting at rest_hand_P_m.
  void simulate(double t_s) {
    if (host.sim_world == nullptr) {
      model.simulate_until(t_s, rest_hand_P_m);
      return;
    }
    const mhd_sim_world& w = *host.sim_world;
    BasePose base;
    w.get_base_pose(w.context, &base.x_m, &base.z_m, &base.heading_rad);
    Eigen::Vector3d p_W;
    w.get_hand(w.context, p_W.data());
    model.simulate_until(t_s, base, p_W);
  }
};

constexpr std::array kParams{
    sdk::choice("hand_model", "kinematic|impedance", "kinematic",
                "how the simulated hand moves: a stiff spring to the intended path, or a mass-spring-damper arm"),
    sdk::number("hand_mass_kg", "kg", "0.55", "impedance hand: the arm's apparent mass", sdk::positive()),
    sdk::number("hand_stiffness_N_per_m", "N/m", nullptr,
                "the hand's spring to the intended path (default 2000 kinematic, 135 impedance)", sdk::positive()),
    sdk::number("hand_damping_Ns_per_m", "N s/m", "6.5", "impedance hand: the arm's damping", sdk::positive()),
    sdk::number("command_timeout_s", "s", "0.02", "the device's own watchdog: older torques count as zero",
                sdk::positive()),
    sdk::number("position_resolution_m", "m", "3e-05", "tool-point resolution of the encoders; 0: exact",
                sdk::non_negative()),
    sdk::vector3("phantom_position_m", "m", nullptr, "the device frame in the robot frame (default: pomhi.xml's)"),
    sdk::vector3("phantom_rpy_deg", "deg", nullptr, "its roll, pitch, yaw (default: pomhi.xml's)"),
    sdk::vector3("base_position_m", "m", nullptr, "the floor frame in the robot frame (default: pomhi.xml's)"),
    sdk::vector3("base_rpy_deg", "deg", nullptr, "its roll, pitch, yaw (default: pomhi.xml's)"),
    sdk::vector3("hand_P_m", "m", nullptr,
                 "without a simulated world: where the hand rests, device frame (default: the workspace centre)"),
    sdk::text("command_log", nullptr, "a CSV file that receives every command and watchdog firing"),
};

Eigen::Isometry3d read_pose(plugin_support::ParamReader& reader, const char* position_name, const char* rpy_name,
                            const Eigen::Isometry3d& fallback) {
  const std::optional<Eigen::Vector3d> p = reader.optional_vector3(position_name);
  const std::optional<Eigen::Vector3d> rpy_deg = reader.optional_vector3(rpy_name);
  Eigen::Isometry3d X = fallback;
  if (rpy_deg) X.linear() = rotation_from_rpy(*rpy_deg * kDegToRad);
  if (p) X.translation() = *p;
  return X;
}

Config read_config(const mhd_param* params, std::size_t count) {
  plugin_support::ParamReader reader(kParams, params, count);
  Config c;
  PhantomSimConfig& m = c.model;
  const std::string hand_model = reader.optional_text("hand_model").value_or("kinematic");
  if (hand_model == "impedance") {
    m.hand_model = HandModel::Impedance;
    simulation::HandImpedanceParams& h = m.hand_impedance;
    h.mass_kg = reader.positive("hand_mass_kg", h.mass_kg);
    h.stiffness_N_per_m = reader.positive("hand_stiffness_N_per_m", h.stiffness_N_per_m);
    h.damping_Ns_per_m = reader.positive("hand_damping_Ns_per_m", h.damping_Ns_per_m);
  } else if (hand_model == "kinematic") {
    for (const char* impedance_only : {"hand_mass_kg", "hand_damping_Ns_per_m"}) {
      if (reader.given(impedance_only)) {
        throw plugin_support::ParamError("parameter '" + std::string(impedance_only) +
                                         "' applies only to hand_model 'impedance'");
      }
    }
    m.hand_stiffness_N_per_m = reader.positive("hand_stiffness_N_per_m", m.hand_stiffness_N_per_m);
  } else {
    throw plugin_support::ParamError("parameter 'hand_model' must be 'kinematic' or 'impedance', got '" + hand_model + "'");
  }
  m.command_timeout_s = reader.positive("command_timeout_s", m.command_timeout_s);
  m.position_resolution_m = reader.non_negative("position_resolution_m", m.position_resolution_m);
  m.X_robot_phantom = read_pose(reader, "phantom_position_m", "phantom_rpy_deg", m.X_robot_phantom);
  m.X_robot_base = read_pose(reader, "base_position_m", "base_rpy_deg", m.X_robot_base);
  c.rest_hand_P_m = reader.vector3("hand_P_m", m.device.workspace.center_P_m());
  c.command_log = reader.optional_text("command_log").value_or("");
  reader.reject_unknown();
  return c;
}

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err) {
  return guarded_open(err, [&] {
    plugin_support::check_host(host);
    plugin_support::check_sim_world(*host);
    auto* instance = new Instance(*host, read_config(params, param_count));
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
    s.simulate(now);
    s.started = true;
    s.read_once = false;
    s.log_event(now, plugin_support::CommandEvent::Start);
    return MHD_OK;
  });
}

mhd_status stop_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    if (s.started) s.log_event(plugin_support::host_now(s.host), plugin_support::CommandEvent::Stop);
    s.started = false;
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) { delete reinterpret_cast<Instance*>(self); }

/// The PHANToM Premium 1.5's nominal maximum stiffness (SensAble's specification, 3.5 N/mm).
constexpr double kMaxStiffness_N_per_m = 3500.0;

mhd_status device_info(mhd_plugin_instance* self, mhd_device_info* out, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    if (out == nullptr) throw std::invalid_argument("device_info: out is NULL");
    const WorkspaceBox& box = s.model.config().device.workspace;
    mhd_device_info info{};
    info.max_force_N = s.model.config().max_force_N;
    info.max_torque_Nm = 0.0;
    info.max_stiffness_N_per_m = kMaxStiffness_N_per_m;
    info.dof_in = 3;
    info.dof_out = 3;
    info.workspace_box_count = 1;
    for (int i = 0; i < 3; ++i) {
      info.workspace[0].min_m[i] = box.min_P_m[i];
      info.workspace[0].max_m[i] = box.max_P_m[i];
    }
    *out = info;
    return MHD_OK;
  });
}

mhd_status device_read(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (out == nullptr) throw std::invalid_argument("device_read: out is NULL");
    const double t = s.model.time_s();
    if (s.read_once && t == s.last_read_time_s) return MHD_NO_DATA;
    // What the encoders imply: forward kinematics of the reported (quantised) angles.
    const Eigen::Vector3d p = phantom_tool_position(s.model.config().device.geometry, s.model.joint_angles_rad());
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    if (s.read_once && t > s.last_read_time_s) v = (p - s.last_read_p_P_m) / (t - s.last_read_time_s);
    *out = mhd_device_state{t, {p[0], p[1], p[2]}, {v[0], v[1], v[2]}, {1.0, 0.0, 0.0, 0.0}, 0u};
    s.read_once = true;
    s.last_read_time_s = t;
    s.last_read_p_P_m = p;
    return MHD_OK;
  });
}

mhd_status device_write(mhd_plugin_instance* self, const mhd_device_command* command, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (command == nullptr) throw std::invalid_argument("device_write: command is NULL");
    const Eigen::Vector3d force_P(command->force_D_N[0], command->force_D_N[1], command->force_D_N[2]);
    if (!force_P.allFinite()) throw std::invalid_argument("device_write: the force is not finite");
    const Eigen::Vector3d tau_max = s.model.max_joint_torques_Nm();
    const Eigen::Vector3d tau = phantom_joint_torques(s.model.config().device.geometry, s.model.joint_angles_rad(), force_P)
                                    .cwiseMax(-tau_max)
                                    .cwiseMin(tau_max);
    const double now = plugin_support::host_now(s.host);
    s.model.command(tau, now);
    s.log_event(now, plugin_support::CommandEvent::Command, {force_P[0], force_P[1], force_P[2]});
    return MHD_OK;
  });
}

mhd_status simulate_until(mhd_plugin_instance* self, double t_s, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    const bool was_commanded = !s.model.watchdog_stopped();
    s.simulate(t_s);
    if (was_commanded && s.model.watchdog_stopped()) {
      // The device's own watchdog fired: the last torques expired command_timeout_s after they came.
      s.log_event(s.model.command_time_s() + s.model.config().command_timeout_s, plugin_support::CommandEvent::Timeout);
    }
    return MHD_OK;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,  // both from mhd_add_plugin, so the table matches the file name
    .version = "3.0.0",
    .description = "Simulated PHANToM Premium 1.5 held by the simulated hand (spring or impedance): IK, tau = J^T F, "
                   "torque watchdog",
    .open = open_instance,
    .start = start_instance,
    .stop = stop_instance,
    .close = close_instance,
    .params = kParams.data(),
    .param_count = kParams.size(),
    .device_info = device_info,
    .device_read = device_read,
    .device_write = device_write,
    .tracker_read = nullptr,
    .base_read = nullptr,
    .base_write = nullptr,
    .display_write = nullptr,
    .simulate_until = simulate_until,
    .tracker_wait = nullptr,
    .counters = nullptr,
};

}  // namespace
}  // namespace mhd::sim_phantom

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::sim_phantom::kApi : nullptr;
}
