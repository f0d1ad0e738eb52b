#include "fault_injection_support.h"

#include "kinematics/rig.h"
#include "recording/csv_recording_reader.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace mhd::fault_injection_test {

namespace {

fs::path dir_of(const ::testing::TestInfo& info) {
  return fs::path(::testing::TempDir()) /
         fmt::format("fault_injection_{}_{}_{}", static_cast<long>(::getpid()), info.test_suite_name(), info.name());
}

/// A passed case's folder is removed; a failed one's stays for a look (every one stays
/// with MHD_KEEP_TEST_SCRATCH=1 in the environment).
class RemoveScratchOfPassedTests : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo& info) override {
    if (!info.result()->Passed() || std::getenv("MHD_KEEP_TEST_SCRATCH") != nullptr) return;
    std::error_code ignored;
    fs::remove_all(dir_of(info), ignored);
  }
};

[[maybe_unused]] const bool listener_added = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new RemoveScratchOfPassedTests);
  return true;
}();

}  // namespace

fs::path temp_dir() {
  const fs::path dir = dir_of(*::testing::UnitTest::GetInstance()->current_test_info());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

PressGeometry press_geometry(double depth_m) {
  const auto read = read_scene_file(std::string(MHD_SOURCE_DIR) + "/scenes/rigs/pomhi.xml");
  if (!read.ok()) throw std::runtime_error("cannot read scenes/rigs/pomhi.xml");
  const Result<Rig, std::vector<RigError>> rig = Rig::from_scene(*read);
  if (!rig.ok()) throw std::runtime_error("scenes/rigs/pomhi.xml has no complete rig");
  const Pose X_W_robot = rig->X_W_robot_from_base(BasePose{});
  PressGeometry g;
  g.q_free_rad = Eigen::Vector3d(0.0, 0.3, 0.2);
  g.hip_free_W_m = rig->p_W_hip(X_W_robot, g.q_free_rad);
  // Lowering the upper arm (theta2) lowers the tool: find the angle that puts the HIP
  // 1.5 cm lower, then the block top depth_m above it.
  g.q_press_rad = g.q_free_rad;
  for (int i = 0; i < 200; ++i) {
    g.q_press_rad.y() -= 0.002;
    g.hip_press_W_m = rig->p_W_hip(X_W_robot, g.q_press_rad);
    if (g.hip_free_W_m.y() - g.hip_press_W_m.y() >= 0.015) break;
  }
  g.block_top_y_m = g.hip_press_W_m.y() + depth_m;
  // What a Cartesian device reports for those angles (ABI 3): the tool in its frame P.
  g.p_free_P_m = phantom_tool_position(rig->device().geometry, g.q_free_rad);
  g.p_press_P_m = phantom_tool_position(rig->device().geometry, g.q_press_rad);
  return g;
}

fs::path write_scene(const fs::path& dir, const PressGeometry& g, const std::string& plugins,
                     const std::string& server_params, const std::string& scene_elements) {
  const fs::path file = dir / "scene.xml";
  std::ofstream(file) << fmt::format(R"(<?xml version="1.0"?>
<scene version="1" unit="m">
  <include file="{}/scenes/rigs/pomhi.xml"/>
  <object name="block">
    <material stiffness_N_per_m="1000"/>
    <box size="1.6 0.2 1.6"/>
    <pose position="{:.6f} {:.6f} {:.6f}"/>
  </object>
{}
  <plugins>
{}
  </plugins>
  <server>
    <param name="fade_in_s" value="0.1"/>
{}
  </server>
</scene>
)", MHD_SOURCE_DIR, g.hip_press_W_m.x(), g.block_top_y_m - 0.1, g.hip_press_W_m.z(), scene_elements, plugins,
                                     server_params);
  return file;
}

std::string fi_device_xml(const PressGeometry& g, const fs::path& log, double press_at_s, const std::string& extra) {
  return fmt::format(R"(    <plugin kind="device" name="fi_device">
      <param name="p_free_m" value="{:.9f} {:.9f} {:.9f}"/>
      <param name="p_press_m" value="{:.9f} {:.9f} {:.9f}"/>
      <param name="press_at_s" value="{}"/>
      <param name="command_log" value="{}"/>
{}    </plugin>)",
                     g.p_free_P_m.x(), g.p_free_P_m.y(), g.p_free_P_m.z(), g.p_press_P_m.x(), g.p_press_P_m.y(),
                     g.p_press_P_m.z(), press_at_s, log.string(), extra);
}

Loaded load(const fs::path& file) {
  Loaded l;
  auto read = read_scene_file(file);
  for (const auto& d : read.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!read.ok()) return l;
  l.description = *read;
  auto compiled = compile_scene(*l.description);
  for (const auto& d : compiled.diagnostics()) ADD_FAILURE() << d.to_string();
  if (compiled.ok()) l.scene = std::move(*compiled.value());
  return l;
}

RunResult run_server(const Loaded& scene, double duration_s, const fs::path& recording, const BasePlanFn& plan) {
  RunResult out;
  if (!scene.scene) return out;
  ServerOptions o;
  o.duration_s = duration_s;
  o.recording = recording;
  o.plugin_path = {MHD_FAULT_INJECTION_PLUGIN_DIR};
  o.plan_base = plan;
  auto build = HapticServer::open(*scene.description, *scene.scene, o);
  for (const auto& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!build.ok()) return out;
  out.opened = true;
  out.warnings = build->warnings;
  out.settings = build->server->settings();
  out.report = build->server->run();
  return out;
}

int line_of(const fs::path& file, const std::string& text) {
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find(text) != std::string::npos) return n;
  }
  return 0;
}

bool LogRow::is_marker() const { return std::isnan(a); }

std::vector<LogRow> read_log(const fs::path& file) {
  std::vector<LogRow> rows;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    LogRow r;
    const char* p = line.c_str();
    char* end = nullptr;
    double* fields[4] = {&r.t_s, &r.a, &r.b, &r.c};
    for (double* f : fields) {
      *f = std::strtod(p, &end);
      p = end;
    }
    rows.push_back(r);
  }
  return rows;
}

std::vector<RecordingRow> read_rows(const fs::path& file) {
  Result<std::vector<RecordingRow>> r = read_recording(file);
  for (const auto& d : r.diagnostics()) ADD_FAILURE() << d.to_string();
  return std::move(r).value();
}

double force_N(const RecordingRow& r) { return std::hypot(r.force_W_N[0], r.force_W_N[1], r.force_W_N[2]); }

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const fs::path& working_dir, const fs::path& output) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const std::string dir = working_dir.string(), out = output.string();
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::unsetenv("MHD_PLUGIN_PATH");
    ::execv(args[0], args.data());
    ::_exit(127);
  }
}

ChildProcess::~ChildProcess() {
  if (!reaped_) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
}

std::chrono::steady_clock::time_point ChildProcess::kill9() {
  const auto t = std::chrono::steady_clock::now();
  ::kill(pid_, SIGKILL);
  return t;
}

std::optional<int> ChildProcess::wait_for(std::chrono::milliseconds timeout) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      reaped_ = true;
      return status;
    }
    if (std::chrono::steady_clock::now() >= until) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace mhd::fault_injection_test
