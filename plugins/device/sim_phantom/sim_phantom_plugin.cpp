// The sim_phantom device plugin: the C ABI over PhantomSimModel. A Cartesian device (ABI 4)
// as a vendor SDK is: it reports the tool point in its frame P, from the joint angles its
// encoders give (the thesis's forward kinematics), and maps the force it receives to motor
// torques itself, tau = J_P^T F (thesis ch. 5.2), clamped to its motors' limits. Torques are
// stamped with the host clock when they arrive; the host advances the device with simulate_until(),
// which reads the hand and the base pose from the scene's simulated world
// (sim_world/sim_session.h; until a hand is placed there, a fixed hand, parameter
// hand_P_m, in the device frame). hand_model selects the kinematic
// hand (a stiff spring) or the impedance hand (a mass-spring-damper pushed by the force). With command_log, every command
// and every firing of the command watchdog goes to a CSV (sim_common/command_log.h).
// docs/sim_phantom.md.

#include "sim_phantom_model.h"
#include "sim_common/command_log.h"
#include "sim_common/simulated_device.h"
#include "sim_world/sim_session.h"

#include "geometry/pose.h"

#include <mhd/plugin_sdk.hpp>

#include <Eigen/Geometry>

#include <array>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

namespace mhd::sim_phantom {

using plugin_support::CommandEvent;

/// The PHANToM Premium 1.5's nominal maximum stiffness (SensAble's specification, 3.5 N/mm).
constexpr double kMaxStiffness_N_per_m = 3500.0;

class SimPhantomPlugin {
 public:
  static constexpr std::array kParams = sdk::join(plugin_support::kSimulatedHandParams, std::array{
      sdk::number("command_timeout_s", "s", "0.02", "the device's own watchdog: older torques count as zero",
                  sdk::between(0.001, 1)),
      sdk::number("position_resolution_m", "m", "3e-05", "tool-point resolution of the encoders; 0: exact",
                  sdk::between(0, 0.01)),
      sdk::vector3("phantom_position_m", "m", nullptr, "the device frame in the robot frame (default: pomhi.xml's)",
                   sdk::between(-10, 10)),
      sdk::vector3("phantom_rpy_deg", "deg", nullptr, "its roll, pitch, yaw (default: pomhi.xml's)",
                   sdk::between(-360, 360)),
      sdk::vector3("base_position_m", "m", nullptr, "the floor frame in the robot frame (default: pomhi.xml's)",
                   sdk::between(-10, 10)),
      sdk::vector3("base_rpy_deg", "deg", nullptr, "its roll, pitch, yaw (default: pomhi.xml's)",
                   sdk::between(-360, 360)),
      sdk::vector3("hand_P_m", "m", nullptr,
                   "while the simulated world has no hand: where it rests, device frame (default: the workspace centre)",
                   sdk::between(-10, 10)),
      sdk::text("command_log", nullptr, "a CSV file that receives every command and watchdog firing"),
  });

  SimPhantomPlugin(const mhd_host& host, const sdk::Params& params)
      : host_(host), session_(sim_world::SimSession::acquire(host)), model_(read_config(params)),
        rest_hand_P_m_(params.optional_vector3<Eigen::Vector3d>("hand_P_m").value_or(workspace_center())) {
    if (const auto file = params.optional_text("command_log")) {
      log_ = std::make_unique<plugin_support::CommandLog>(*file, std::array{"force_x_N", "force_y_N", "force_z_N"});
    }
  }

  void start() {
    const double now = sdk::host_now(host_);
    model_.start(now);
    simulate(now);
    read_once_ = false;
    // The scene's user walks on the session's thread: this plugin's calls run on the
    // haptic thread, which must not lock, and on a desk nothing else moves the user.
    user_runner_ = sim_world::SimSession::run_user(session_, host_);
    log_event(now, CommandEvent::Start);
  }
  void stop() {
    user_runner_.reset();
    log_event(sdk::host_now(host_), CommandEvent::Stop);
  }

  void device_info(mhd_device_info& out) const {
    const WorkspaceBox& box = model_.config().device.workspace;
    out = plugin_support::one_box_device_info(model_.config().max_force_N, kMaxStiffness_N_per_m, box.min_P_m,
                                              box.max_P_m);
  }

  mhd_status device_read(mhd_device_state& out) {
    const double t = model_.time_s();
    if (read_once_ && t == last_read_time_s_) return MHD_NO_DATA;
    // What the encoders imply: forward kinematics of the reported (quantised) angles.
    const Eigen::Vector3d p = phantom_tool_position(model_.config().device.geometry, model_.joint_angles_rad());
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    if (read_once_ && t > last_read_time_s_) v = (p - last_read_p_P_m_) / (t - last_read_time_s_);
    out = mhd_device_state{t, {p[0], p[1], p[2]}, {v[0], v[1], v[2]}, {1.0, 0.0, 0.0, 0.0}, 0u};
    read_once_ = true;
    last_read_time_s_ = t;
    last_read_p_P_m_ = p;
    return MHD_OK;
  }

  void device_write(const mhd_device_command& command) {
    const Eigen::Vector3d force_P(command.force_D_N[0], command.force_D_N[1], command.force_D_N[2]);
    if (!force_P.allFinite()) throw std::invalid_argument("device_write: the force is not finite");
    const Eigen::Vector3d tau_max = model_.max_joint_torques_Nm();
    const Eigen::Vector3d tau = phantom_joint_torques(model_.config().device.geometry, model_.joint_angles_rad(), force_P)
                                    .cwiseMax(-tau_max)
                                    .cwiseMin(tau_max);
    const double now = sdk::host_now(host_);
    // A host frozen between simulate_until and this call: the device's watchdog fired in
    // the gap, so the device lives through it before the new command applies.
    if (!model_.watchdog_stopped() && now - model_.command_time_s() > model_.config().command_timeout_s) {
      simulate_until(now);
    }
    model_.command(tau, now);
    log_event(now, CommandEvent::Command, {force_P[0], force_P[1], force_P[2]});
  }

  void simulate_until(double t_s) {
    const bool was_commanded = !model_.watchdog_stopped();
    simulate(t_s);
    // One command expires once: a second firing for the same command (the model re-armed
    // and stopped again by a tick on the command's deadline) is not a second event.
    if (was_commanded && model_.watchdog_stopped() && model_.command_time_s() != timed_out_command_s_) {
      timed_out_command_s_ = model_.command_time_s();
      // The device's own watchdog fired: the last torques expired command_timeout_s after they came.
      log_event(model_.command_time_s() + model_.config().command_timeout_s, CommandEvent::Timeout);
    }
  }

 private:
  static PhantomSimConfig read_config(const sdk::Params& params);

  Eigen::Vector3d workspace_center() const { return model_.config().device.workspace.center_P_m(); }

  void log_event(double t_s, CommandEvent event, const std::array<double, 3>& values = {}) noexcept {
    if (log_) log_->add(t_s, event, values);
  }

  /// Evaluates the device at t_s with the world's hand (where the user means it to be),
  /// base pose and lift height, or, while the world has no hand, with the hand resting at rest_hand_P_m.
  void simulate(double t_s) {
    const simulation::SimulatedWorld& w = session_->world();
    if (!w.has_hand()) {
      model_.simulate_until(t_s, rest_hand_P_m_);
      return;
    }
    const simulation::PlanarPose b = w.base_pose();
    BasePose base;
    base.x_m = b.x_m;
    base.z_m = b.z_m;
    base.heading_rad = b.heading_rad;
    model_.simulate_until(t_s, base, w.hand(), w.lift_m());
  }

  mhd_host host_;
  std::shared_ptr<sim_world::SimSession> session_;
  std::unique_ptr<sim_world::UserRunner> user_runner_;  ///< between start and stop
  PhantomSimModel model_;
  Eigen::Vector3d rest_hand_P_m_;
  bool read_once_ = false;
  double last_read_time_s_ = 0.0;
  double timed_out_command_s_ = -1.0;  ///< the command whose expiry was logged last
  Eigen::Vector3d last_read_p_P_m_ = Eigen::Vector3d::Zero();
  std::unique_ptr<plugin_support::CommandLog> log_;  ///< written inside SDK calls only: one producer
};

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

Eigen::Isometry3d read_pose(const sdk::Params& params, const char* position_name, const char* rpy_name,
                            const Eigen::Isometry3d& fallback) {
  const std::optional<Eigen::Vector3d> p = params.optional_vector3<Eigen::Vector3d>(position_name);
  const std::optional<Eigen::Vector3d> rpy_deg = params.optional_vector3<Eigen::Vector3d>(rpy_name);
  Eigen::Isometry3d X = fallback;
  if (rpy_deg) X.linear() = rotation_from_rpy(*rpy_deg * kDegToRad);
  if (p) X.translation() = *p;
  return X;
}

}  // namespace

PhantomSimConfig SimPhantomPlugin::read_config(const sdk::Params& params) {
  PhantomSimConfig m;
  plugin_support::read_simulated_hand(params, m);
  m.command_timeout_s = params.number("command_timeout_s");
  m.position_resolution_m = params.number("position_resolution_m");
  m.X_robot_phantom = read_pose(params, "phantom_position_m", "phantom_rpy_deg", m.X_robot_phantom);
  m.X_robot_base = read_pose(params, "base_position_m", "base_rpy_deg", m.X_robot_base);
  return m;
}

}  // namespace mhd::sim_phantom

MHD_PLUGIN_ENTRY(mhd::sim_phantom::SimPhantomPlugin,
                 {.kind = MHD_PLUGIN_KIND,
                  .name = MHD_PLUGIN_NAME,  // both from mhd_add_plugin, so the table matches the file name
                  .version = "3.0.0",
                  .description = "Simulated PHANToM Premium 1.5 held by the simulated hand (spring or impedance): "
                                 "IK, tau = J^T F, torque watchdog"})
