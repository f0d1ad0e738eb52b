// The sim_delta device plugin: the C ABI over DeltaSimModel (docs/sim_delta.md), a
// Cartesian device (ABI 3) as sim_phantom is. A desk device rides no base, so the
// simulated hand reaches it through its pose in the world, X_WD (parameters
// device_position_m, device_rpy_deg: the scene's <frame name="device">); without a
// simulated world the hand rests at hand_D_m. Deliberately thin: the plugin SDK will
// replace this table and shell code.

#include "sim_delta_model.h"
#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include "geometry/pose.h"

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>

#include <array>
#include <atomic>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace mhd::sim_delta {
namespace {

struct Config {
  DeltaSimConfig model;
  Pose X_WD = Pose::Identity();
  Eigen::Vector3d rest_hand_D_m = Eigen::Vector3d::Zero();
};

struct Instance {
  Instance(const mhd_host& h, const Config& c)
      : host(h), model(c.model), X_DW(c.X_WD.inverse(Eigen::Isometry)), rest_hand_D_m(c.rest_hand_D_m) {}

  std::atomic<bool> in_call{false};  ///< plugin_support::with_instance's
  mhd_host host;
  DeltaSimModel model;
  Pose X_DW;
  Eigen::Vector3d rest_hand_D_m;
  bool started = false;  ///< plugin_support::with_instance's (Need::Running)
  bool read_once = false;
  double last_read_time_s = 0.0;

  /// The device at t_s with the world's hand in D, or the resting hand without a world.
  void simulate(double t_s) {
    if (host.sim_world == nullptr) {
      model.simulate_until(t_s, rest_hand_D_m);
      return;
    }
    Eigen::Vector3d p_W_hand;
    host.sim_world->get_hand(host.sim_world->context, p_W_hand.data());
    model.simulate_until(t_s, X_DW * p_W_hand);
  }
};

constexpr std::array kParams{
    sdk::choice("hand_model", "kinematic|impedance", "kinematic",
                "how the simulated hand moves: a stiff spring to the intended path, or a mass-spring-damper arm"),
    sdk::number("hand_mass_kg", "kg", "0.55", "impedance hand: the arm's apparent mass", sdk::positive()),
    sdk::number("hand_stiffness_N_per_m", "N/m", nullptr,
                "the hand's spring to the intended path (default 2000 kinematic, 135 impedance)", sdk::positive()),
    sdk::number("hand_damping_Ns_per_m", "N s/m", "6.5", "impedance hand: the arm's damping", sdk::positive()),
    sdk::number("command_timeout_s", "s", "0.02", "the device's own watchdog: older forces count as zero",
                sdk::positive()),
    sdk::vector3("device_position_m", "m", "0 0 0", "the device frame D in the world (the scene's frame 'device')"),
    sdk::vector3("device_rpy_deg", "deg", "0 0 0", "its roll, pitch, yaw"),
    sdk::vector3("hand_D_m", "m", nullptr,
                 "without a simulated world: where the hand rests, device frame (default: the workspace centre)"),
};

Config read_config(const mhd_param* params, std::size_t count) {
  plugin_support::ParamReader reader(kParams, params, count);
  Config c;
  DeltaSimConfig& m = c.model;
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
  const Eigen::Vector3d rpy_deg = reader.vector3("device_rpy_deg", Eigen::Vector3d::Zero());
  c.X_WD.linear() = rotation_from_rpy(rpy_deg * (std::numbers::pi / 180.0));
  c.X_WD.translation() = reader.vector3("device_position_m", Eigen::Vector3d::Zero());
  c.rest_hand_D_m = reader.vector3("hand_D_m", m.workspace.center_D_m());
  reader.reject_unknown();
  return c;
}

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err) {
  return plugin_support::guarded_open(err, [&] {
    plugin_support::check_host(host);
    plugin_support::check_sim_world(*host);
    auto* instance = new Instance(*host, read_config(params, param_count));
    return reinterpret_cast<mhd_plugin_instance*>(instance);
  });
}

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
    return MHD_OK;
  });
}

mhd_status stop_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [](Instance& s) {
    s.started = false;
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) { delete reinterpret_cast<Instance*>(self); }

/// Not Novint's (it publishes none): MHD's bound for the simulated delta, the stiffest
/// material in scenes/common/materials.xml.
constexpr double kMaxStiffness_N_per_m = 2000.0;

mhd_status device_info(mhd_plugin_instance* self, mhd_device_info* out, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    if (out == nullptr) throw std::invalid_argument("device_info: out is NULL");
    const DeltaWorkspaceBox& box = s.model.config().workspace;
    mhd_device_info info{};
    info.max_force_N = s.model.config().max_force_N;
    info.max_stiffness_N_per_m = kMaxStiffness_N_per_m;
    info.dof_in = 3;
    info.dof_out = 3;
    info.workspace_box_count = 1;
    for (int i = 0; i < 3; ++i) {
      info.workspace[0].min_m[i] = box.min_D_m[i];
      info.workspace[0].max_m[i] = box.max_D_m[i];
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
    const Eigen::Vector3d& p = s.model.p_D_tool_m();
    const Eigen::Vector3d& v = s.model.v_D_tool_mps();
    *out = mhd_device_state{t, {p[0], p[1], p[2]}, {v[0], v[1], v[2]}, {1.0, 0.0, 0.0, 0.0}, 0u};
    s.read_once = true;
    s.last_read_time_s = t;
    return MHD_OK;
  });
}

mhd_status device_write(mhd_plugin_instance* self, const mhd_device_command* command, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (command == nullptr) throw std::invalid_argument("device_write: command is NULL");
    const Eigen::Vector3d force_D(command->force_D_N[0], command->force_D_N[1], command->force_D_N[2]);
    s.model.command(force_D, plugin_support::host_now(s.host));  // throws on a non-finite force
    return MHD_OK;
  });
}

mhd_status simulate_until(mhd_plugin_instance* self, double t_s, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    s.simulate(t_s);
    return MHD_OK;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,
    .version = "1.0.0",
    .description = "Simulated delta (Novint Falcon-like) on a desk, held by the simulated hand (spring or impedance)",
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
}  // namespace mhd::sim_delta

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::sim_delta::kApi : nullptr;
}
