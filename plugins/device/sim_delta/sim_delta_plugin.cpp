// The sim_delta device plugin: the C ABI (through the plugin SDK) over DeltaSimModel
// (docs/sim_delta.md), a Cartesian device (ABI 4) as sim_phantom is. A desk device rides no
// base, so the simulated hand reaches it through its pose in the world, X_WD (parameters
// device_position_m, device_rpy_deg: the scene's <frame name="device">); until a hand is
// placed in the scene's simulated world (sim_world/sim_session.h) it rests at hand_D_m.

#include "sim_delta_model.h"
#include "sim_common/simulated_device.h"
#include "sim_world/sim_session.h"

#include "geometry/pose.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd::sim_delta {

/// Not Novint's (it publishes none): MHD's bound for the simulated delta, the stiffest
/// material in scenes/common/materials.xml.
constexpr double kMaxStiffness_N_per_m = 2000.0;

class SimDeltaPlugin {
 public:
  static constexpr std::array kParams = sdk::join(plugin_support::kSimulatedHandParams, std::array{
      sdk::number("command_timeout_s", "s", "0.02", "the device's own watchdog: older forces count as zero",
                  sdk::between(0.001, 1)),
      sdk::vector3("device_position_m", "m", "0 0 0", "the device frame D in the world (the scene's frame 'device')",
                   sdk::between(-1000, 1000)),
      sdk::vector3("device_rpy_deg", "deg", "0 0 0", "its roll, pitch, yaw", sdk::between(-360, 360)),
      sdk::vector3("hand_D_m", "m", nullptr,
                   "while the simulated world has no hand: where it rests, device frame (default: the workspace centre)",
                   sdk::between(-10, 10)),
  });

  SimDeltaPlugin(const mhd_host& host, const sdk::Params& params)
      : host_(host), session_(sim_world::SimSession::acquire(host)), model_(read_config(params)),
        X_DW_(read_X_WD(params).inverse(Eigen::Isometry)) {
    rest_hand_D_m_ =
        params.optional_vector3<Eigen::Vector3d>("hand_D_m").value_or(model_.config().workspace.center_D_m());
  }

  void start() {
    const double now = sdk::host_now(host_);
    model_.start(now);
    simulate_until(now);
    // The scene's user walks on the session's thread (device calls run on the haptic
    // thread, which must not lock).
    user_runner_ = sim_world::SimSession::run_user(session_, host_);
    read_once_ = false;
  }
  void stop() { user_runner_.reset(); }

  void device_info(mhd_device_info& out) const {
    const DeltaWorkspaceBox& box = model_.config().workspace;
    out = plugin_support::one_box_device_info(model_.config().max_force_N, kMaxStiffness_N_per_m, box.min_D_m,
                                              box.max_D_m);
  }

  mhd_status device_read(mhd_device_state& out) {
    const double t = model_.time_s();
    if (read_once_ && t == last_read_time_s_) return MHD_NO_DATA;
    const Eigen::Vector3d& p = model_.p_D_tool_m();
    const Eigen::Vector3d& v = model_.v_D_tool_mps();
    out = mhd_device_state{t, {p[0], p[1], p[2]}, {v[0], v[1], v[2]}, {1.0, 0.0, 0.0, 0.0}, 0u};
    read_once_ = true;
    last_read_time_s_ = t;
    return MHD_OK;
  }

  void device_write(const mhd_device_command& command) {
    const Eigen::Vector3d force_D(command.force_D_N[0], command.force_D_N[1], command.force_D_N[2]);
    model_.command(force_D, sdk::host_now(host_));  // throws on a non-finite force
  }

  /// The device at t_s with the world's hand in D, or the resting hand while the world has none.
  void simulate_until(double t_s) {
    const simulation::SimulatedWorld& w = session_->world();
    if (!w.has_hand()) {
      model_.simulate_until(t_s, rest_hand_D_m_);
      return;
    }
    model_.simulate_until(t_s, X_DW_ * w.hand());
  }

 private:
  static DeltaSimConfig read_config(const sdk::Params& params) {
    DeltaSimConfig m;
    plugin_support::read_simulated_hand(params, m);
    m.command_timeout_s = params.number("command_timeout_s");
    return m;
  }

  static Pose read_X_WD(const sdk::Params& params) {
    Pose X_WD = Pose::Identity();
    const Eigen::Vector3d rpy_deg = params.vector3<Eigen::Vector3d>("device_rpy_deg");
    X_WD.linear() = rotation_from_rpy(rpy_deg * (std::numbers::pi / 180.0));
    X_WD.translation() = params.vector3<Eigen::Vector3d>("device_position_m");
    return X_WD;
  }

  mhd_host host_;
  std::shared_ptr<sim_world::SimSession> session_;
  std::unique_ptr<sim_world::UserRunner> user_runner_;  ///< between start and stop
  DeltaSimModel model_;
  Pose X_DW_;
  Eigen::Vector3d rest_hand_D_m_ = Eigen::Vector3d::Zero();
  bool read_once_ = false;
  double last_read_time_s_ = 0.0;
};

}  // namespace mhd::sim_delta

MHD_PLUGIN_ENTRY(mhd::sim_delta::SimDeltaPlugin,
                 {.kind = MHD_PLUGIN_KIND,
                  .name = MHD_PLUGIN_NAME,  // both from mhd_add_plugin, so the table matches the file name
                  .version = "1.0.0",
                  .description = "Simulated delta (Novint Falcon-like) on a desk, held by the simulated hand (spring "
                                 "or impedance)"})
