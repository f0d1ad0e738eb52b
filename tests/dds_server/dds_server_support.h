#pragma once
// What tests/dds_server's tests and its benchmark share: the haptic server's scene on the
// thesis rig with the DDS tracker and state plugins, a replay file for the tracker server
// process, the server run on a thread of its own, and the recording read back.

#include "haptic_server/haptic_server.h"
#include "kinematics/rig.h"
#include "scene/scene_description.h"
#include "scene_compiler/compiled_scene.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace mhd::dds_server_test {

/// fault_device's fixed joint angles (tests/haptic_server/plugins/fault_device.cpp).
inline const Eigen::Vector3d kDeviceJoints_rad{0.0, 0.3, 0.2};
/// How deep the wall's face lies behind the HIP once the base is at the origin.
inline constexpr double kWallPenetration_m = 0.005;
inline constexpr double kWallStiffness_N_per_m = 1000.0;

/// The thesis rig (scenes/rigs/pomhi.xml).
[[nodiscard]] Rig thesis_rig();
/// The HIP with the base at `base` and fault_device's joint angles.
[[nodiscard]] Eigen::Vector3d hip_at(const Rig& rig, const BasePose& base);

struct SceneOptions {
  std::uint32_t domain_id = 0;
  std::uint32_t rig_id = 1;
  bool log_base = true;            ///< the dds_server_log_base base, logging to base_log
  std::filesystem::path base_log;
  bool state_display = true;       ///< the dds_state display
  bool ros2_display = false;       ///< the ros2_state display (ROS 2 topics, namespace mhd/rig<rig_id>)
  std::string server_params;       ///< extra <param .../> lines for <server>
};

/// A scene on the thesis rig with a wall whose -x face is kWallPenetration_m on the -x
/// side of the HIP at the base origin (a base moving +x towards the origin pushes the
/// hand into it), fault_device, the dds tracker and the options' base and display.
std::filesystem::path write_server_scene(const std::filesystem::path& dir, const SceneOptions& options);

/// A replay CSV for the tracker server: sensor 0 (the base sensor) at 200 Hz for
/// duration_s, with the base at x = -approach_m for hold_s, then moving +x at
/// approach_mps until it reaches the origin, where it stays; and sensor 1, the head of a user
/// standing 3 m behind (world x = -3), outside the base keep-out.
void write_approach_replay(const std::filesystem::path& file, const Rig& rig, double duration_s, double hold_s,
                           double approach_m, double approach_mps);

/// A one-plugin scene for the tracker server playing `replay`.
std::filesystem::path write_tracker_scene(const std::filesystem::path& dir, const std::filesystem::path& replay);

/// The tracker-server command's arguments (tests/dds's dds_test_tracker_server).
[[nodiscard]] std::vector<std::string> tracker_server_args(const std::filesystem::path& scene, std::uint32_t domain,
                                                           std::uint32_t rig, double duration_s);

/// A scene read and compiled, kept alive for the server; errors in `errors`.
struct LoadedScene {
  std::optional<SceneDescription> description;
  std::optional<CompiledScene> compiled;
  std::vector<std::string> errors;
};
[[nodiscard]] LoadedScene load_scene(const std::filesystem::path& file);
/// The same, with the description changed by `edit` before it is compiled (a test's
/// domain id or identity in a shipped scene's plugins).
[[nodiscard]] LoadedScene load_scene(const std::filesystem::path& file,
                                     const std::function<void(SceneDescription&)>& edit);

/// The plugin folders: this folder's test plugins, fault_device's, the build's.
[[nodiscard]] std::vector<std::filesystem::path> plugin_dirs();

/// HapticServer::run() on a thread; stop() requests the stop and returns the report.
class ServerThread {
 public:
  ServerThread(const LoadedScene& scene, ServerOptions options);
  ~ServerThread();
  ServerThread(const ServerThread&) = delete;
  ServerThread& operator=(const ServerThread&) = delete;
  [[nodiscard]] bool opened() const { return server_ != nullptr; }
  [[nodiscard]] const std::vector<std::string>& errors() const { return errors_; }
  ServerReport stop();

 private:
  std::unique_ptr<HapticServer> server_;
  std::vector<std::string> errors_;
  std::thread thread_;
  ServerReport report_;
  bool stopped_ = false;
};

/// One row of the recording (docs/haptic_server.md, "Recording"), the columns used here.
struct Row {
  double t_s = 0.0;
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy_W_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_W_N = Eigen::Vector3d::Zero();
  double base_x_m = 0.0, base_z_m = 0.0, base_heading_rad = 0.0;
  double tracker_age_s = -1.0;
  double safety_gain = 0.0;
  bool contact = false;
};
/// Every complete row of a recording.
[[nodiscard]] std::vector<Row> read_recording(const std::filesystem::path& file);

/// One command of dds_server_log_base's log.
struct LoggedCommand {
  double t_s = 0.0, vx_mps = 0.0, vz_mps = 0.0, omega_radps = 0.0;
  [[nodiscard]] bool zero() const { return vx_mps == 0.0 && vz_mps == 0.0 && omega_radps == 0.0; }
};
[[nodiscard]] std::vector<LoggedCommand> read_command_log(const std::filesystem::path& file);

}  // namespace mhd::dds_server_test
