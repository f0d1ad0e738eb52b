#include "dds_server_support.h"

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <fmt/core.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mhd::dds_server_test {

namespace fs = std::filesystem;

Rig thesis_rig() {
  const auto read = read_scene_file(fs::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml");
  if (!read.ok()) throw std::runtime_error("scenes/rigs/pomhi.xml does not read");
  auto built = Rig::from_scene(*read);
  if (!built.ok()) throw std::runtime_error("scenes/rigs/pomhi.xml: " + built.error().front().to_string());
  return *built;
}

Eigen::Vector3d hip_at(const Rig& rig, const BasePose& base) {
  return rig.p_W_hip(rig.X_W_robot_from_base(base), kDeviceJoints_rad);
}

fs::path write_server_scene(const fs::path& dir, const SceneOptions& o) {
  const Eigen::Vector3d hip = hip_at(thesis_rig(), BasePose{});
  const double size_m = 0.1;
  const Eigen::Vector3d wall_center(hip.x() - kWallPenetration_m + size_m / 2, hip.y(), hip.z());
  std::string plugins = fmt::format(R"(
    <plugin kind="device" name="fault_device"/>
    <plugin kind="tracker" name="dds">
      <param name="rig_id" value="{0}"/>
      <param name="domain_id" value="{1}"/>
    </plugin>)", o.rig_id, o.domain_id);
  if (o.log_base) {
    plugins += fmt::format(R"(
    <plugin kind="base" name="dds_server_log_base">
      <param name="command_log" value="{}"/>
    </plugin>)", o.base_log.string());
  }
  if (o.state_display) {
    plugins += fmt::format(R"(
    <plugin kind="display" name="dds_state">
      <param name="rig_id" value="{0}"/>
      <param name="domain_id" value="{1}"/>
    </plugin>)", o.rig_id, o.domain_id);
  }
  if (o.ros2_display) {
    plugins += fmt::format(R"(
    <plugin kind="display" name="ros2_state">
      <param name="rig_id" value="{0}"/>
      <param name="domain_id" value="{1}"/>
    </plugin>)", o.rig_id, o.domain_id);
  }
  const fs::path file = dir / "haptic_server.xml";
  std::ofstream(file) << fmt::format(R"(<?xml version="1.0"?>
<scene version="1" unit="m">
  <include file="{}/scenes/rigs/pomhi.xml"/>
  <object name="wall">
    <material stiffness_N_per_m="{}"/>
    <box size="{} {} {}"/>
    <pose position="{:.9f} {:.9f} {:.9f}"/>
  </object>
  <plugins>{}
  </plugins>
  <server>
    <param name="fade_in_s" value="0.1"/>{}
  </server>
</scene>
)", MHD_SOURCE_DIR, kWallStiffness_N_per_m, size_m, size_m, size_m, wall_center.x(), wall_center.y(),
                                     wall_center.z(), plugins, o.server_params);
  return file;
}

void write_approach_replay(const fs::path& file, const Rig& rig, double duration_s, double hold_s, double approach_m,
                           double approach_mps) {
  std::ofstream out(file);
  out << "timestamp_s,sensor_id,sequence,px,py,pz,qw,qx,qy,qz\n";
  const double period_s = 0.005;
  for (int i = 0; i * period_s < duration_s; ++i) {
    const double t = i * period_s;
    const double x = std::min(0.0, -approach_m + approach_mps * std::max(0.0, t - hold_s));
    const Pose X = rig.X_is900_base_sensor_from_base(BasePose{x, 0.0, 0.0});
    const Eigen::Quaterniond q(X.rotation());
    out << fmt::format("{:.3f},0,{},{:.9f},{:.9f},{:.9f},{:.12f},{:.12f},{:.12f},{:.12f}\n", t, i, X.translation().x(),
                       X.translation().y(), X.translation().z(), q.w(), q.x(), q.y(), q.z());
    // The head (sensor 1) of a user standing 3 m behind: the guard moves the base on fresh
    // head data only, and this user is outside the keep-out whatever the data's age.
    const Eigen::Vector3d p_T_head = rig.X_W_is900().inverse() * Eigen::Vector3d(-3.0, 1.7, 0.0);
    out << fmt::format("{:.3f},1,{},{:.9f},{:.9f},{:.9f},1,0,0,0\n", t, i, p_T_head.x(), p_T_head.y(), p_T_head.z());
  }
}

fs::path write_tracker_scene(const fs::path& dir, const fs::path& replay) {
  const fs::path file = dir / "tracker_server.xml";
  std::ofstream(file) << fmt::format(R"(<?xml version="1.0"?>
<scene version="1" name="dds_server_replay">
  <plugins>
    <plugin kind="tracker" name="replay">
      <param name="file" value="{}"/>
    </plugin>
  </plugins>
</scene>
)", replay.string());
  return file;
}

std::vector<std::string> tracker_server_args(const fs::path& scene, std::uint32_t domain, std::uint32_t rig,
                                             double duration_s) {
  return {MHD_DDS_TEST_TRACKER_SERVER, "tracker-server", scene.string(), "--domain-id", std::to_string(domain),
          "--rig-id", std::to_string(rig), "--duration", std::to_string(duration_s), "--plugin-path",
          MHD_DDS_TEST_PLUGIN_DIR};
}

LoadedScene load_scene(const fs::path& file) { return load_scene(file, {}); }

LoadedScene load_scene(const fs::path& file, const std::function<void(SceneDescription&)>& edit) {
  LoadedScene l;
  auto read = read_scene_file(file);
  for (const auto& d : read.diagnostics()) l.errors.push_back(d.to_string());
  if (!read.ok()) return l;
  l.description = *read;
  if (edit) edit(*l.description);
  auto compiled = compile_scene(*l.description);
  for (const auto& d : compiled.diagnostics()) l.errors.push_back(d.to_string());
  if (compiled.ok()) l.compiled = std::move(*compiled.value());
  return l;
}

std::vector<fs::path> plugin_dirs() {
  std::vector<fs::path> dirs;
  std::stringstream s(MHD_DDS_SERVER_PLUGIN_DIRS);
  for (std::string dir; std::getline(s, dir, ':');) dirs.emplace_back(dir);
  return dirs;
}

ServerThread::ServerThread(const LoadedScene& scene, ServerOptions options) {
  if (!scene.compiled) {
    errors_ = scene.errors;
    return;
  }
  auto build = HapticServer::open(*scene.description, *scene.compiled, std::move(options));
  for (const auto& d : build.diagnostics()) errors_.push_back(d.to_string());
  if (build.ok()) server_ = std::move(build->server);
  if (server_) thread_ = std::thread([this] { report_ = server_->run(); });
}

ServerThread::~ServerThread() { (void)stop(); }

ServerReport ServerThread::stop() {
  if (!stopped_ && server_) {
    server_->request_stop();
    thread_.join();
    stopped_ = true;
  }
  return report_;
}

std::vector<Row> read_recording(const fs::path& file) {
  std::vector<Row> rows;
  std::ifstream in(file);
  std::string line;
  // Columns by name (the header), so a column added to the recording does not shift them.
  std::vector<std::string> header;
  if (!std::getline(in, line)) return rows;
  {
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) header.push_back(cell);
  }
  const auto column = [&](const char* name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw std::runtime_error(fmt::format("{}: no column '{}'", file.string(), name));
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t t = column("t_s"), hip = column("hip_x_m"), proxy = column("proxy_x_m"),
                    force = column("force_x_N"), base_x = column("base_x_m"), base_z = column("base_z_m"),
                    heading = column("base_heading_rad"), age = column("tracker_age_s"),
                    gain = column("safety_gain"), contact = column("contact");
  std::vector<double> v;
  while (std::getline(in, line)) {
    v.clear();
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::strtod(cell.c_str(), nullptr));
    if (v.size() != header.size()) continue;  // a partial last line
    Row r;
    r.t_s = v[t];
    r.p_W_hip = {v[hip], v[hip + 1], v[hip + 2]};
    r.proxy_W_m = {v[proxy], v[proxy + 1], v[proxy + 2]};
    r.force_W_N = {v[force], v[force + 1], v[force + 2]};
    r.base_x_m = v[base_x];
    r.base_z_m = v[base_z];
    r.base_heading_rad = v[heading];
    r.tracker_age_s = v[age];
    r.safety_gain = v[gain];
    r.contact = v[contact] != 0.0;
    rows.push_back(r);
  }
  return rows;
}

std::vector<LoggedCommand> read_command_log(const fs::path& file) {
  std::vector<LoggedCommand> commands;
  std::ifstream in(file);
  LoggedCommand c;
  while (in >> c.t_s >> c.vx_mps >> c.vz_mps >> c.omega_radps) commands.push_back(c);
  return commands;
}

}  // namespace mhd::dds_server_test
