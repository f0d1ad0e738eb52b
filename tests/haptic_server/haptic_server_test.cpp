// The haptic server with real plugins through the real dlopen path: the simulated rig on
// the dolphin scene, and test plugins that fail on cue (plugins/), each run ending in the
// safe state with a message naming the plugin and its scene line.
#include "haptic_server/haptic_server.h"

#include "fault_plugin_log.h"
#include "kinematics/rig.h"
#include "recording/csv_recording.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace mhd;
namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path temp_dir() {
  const fs::path dir = fs::path(::testing::TempDir()) / "haptic_server_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  return dir;
}

struct Loaded {
  std::optional<SceneDescription> description;
  std::optional<CompiledScene> scene;
};

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

ServerOptions options_for(double duration_s) {
  ServerOptions o;
  o.duration_s = duration_s;
  o.plugin_path = {MHD_FAULT_PLUGIN_DIR};
  return o;
}

/// A scene on the thesis rig with a floor, the given <plugins> content and extra XML.
fs::path write_scene(const fs::path& dir, const std::string& plugins, const std::string& extra = "") {
  const fs::path file = dir / "scene.xml";
  std::ofstream(file) << fmt::format(R"(<?xml version="1.0"?>
<scene version="1" unit="m">
  <include file="{}/scenes/rigs/pomhi.xml"/>
  <object name="floor">
    <material stiffness_N_per_m="1000"/>
    <box size="4 0.1 4"/>
    <pose position="0 -0.05 0"/>
  </object>
  <plugins>
{}
  </plugins>
{}
</scene>
)", MHD_SOURCE_DIR, plugins, extra);
  return file;
}

using CommandLog = mhd::test::FaultPluginLog;
CommandLog read_log(const fs::path& file) { return mhd::test::read_fault_plugin_log(file); }

int scene_line_of(const fs::path& file, const std::string& text) {
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find(text) != std::string::npos) return n;
  }
  return 0;
}

TEST(HapticServer, RunsTheDolphinSceneOnSimulatedHardwareAndRecordsEveryTick) {
  const fs::path dir = temp_dir();
  Loaded l = load(std::string(MHD_SOURCE_DIR) + "/scenes/dolphin.xml");
  ASSERT_TRUE(l.scene);
  ServerOptions o = options_for(1.5);
  o.recording = dir / "dolphin.csv";
  auto build = HapticServer::open(*l.description, *l.scene, o);
  for (const auto& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_EQ(r.ended_by, RunEnd::Duration);
  EXPECT_GT(r.status.ticks, 100u);
  EXPECT_GT(r.status.tracker_samples, 50u);
  EXPECT_EQ(r.status.tracker_rejected, 0u);
  EXPECT_TRUE(r.zero_force_sent);
  EXPECT_TRUE(r.base_stop_sent);
  EXPECT_EQ(r.recording_dropped, 0u);
  EXPECT_EQ(r.recording_rows, r.status.ticks);
  EXPECT_EQ(r.proxy_budget_exhausted_ticks, 0u);  // an ordinary run stays within the proxy's budget

  std::ifstream csv(o.recording);
  std::string header;
  ASSERT_TRUE(std::getline(csv, header));
  EXPECT_EQ(header, recording_csv_header());
  std::size_t rows = 0, rows_with_hip = 0;
  for (std::string line; std::getline(csv, line); ++rows) {
    if (line.find("nan") == std::string::npos) ++rows_with_hip;
  }
  EXPECT_EQ(rows, r.recording_rows);
  EXPECT_GT(rows_with_hip, rows / 2);  // the HIP is known once the first base pose is in
}

TEST(HapticServer, CountsTheTicksWhoseProxyRanOutOfItsWorkBudget) {
  // One sweep a tick is too few for a hand stroking in and out of the box's top face.
  Loaded l = load(std::string(MHD_SOURCE_DIR) + "/tests/data/server/touch_box.xml");
  ASSERT_TRUE(l.scene);
  l.scene->proxy.max_sweeps_per_tick = 1;
  auto build = HapticServer::open(*l.description, *l.scene, options_for(1.5));
  for (const auto& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_GT(r.proxy_budget_exhausted_ticks, 0u);
  EXPECT_LE(r.proxy_budget_exhausted_ticks, r.status.ticks);
}

/// Runs `file` to its end and checks, from the plugins' own logs, that the device's last
/// command was zero torque and the base's last a zero twist.
void expect_safe_stop_after(const ServerReport& r, const fs::path& device_log, const fs::path& base_log) {
  EXPECT_EQ(r.ended_by, RunEnd::Fault);  // `mhd run` exits 3, not ended by the 30 s duration
  EXPECT_TRUE(r.zero_force_sent);
  EXPECT_TRUE(r.base_stop_sent);
  const CommandLog device = read_log(device_log);
  EXPECT_GT(device.count, 0u);
  EXPECT_EQ(device.a, 0.0);
  EXPECT_EQ(device.b, 0.0);
  EXPECT_EQ(device.c, 0.0);
  const CommandLog base = read_log(base_log);
  EXPECT_GT(base.count, 0u);
  EXPECT_EQ(base.a, 0.0);
  EXPECT_EQ(base.b, 0.0);
  EXPECT_EQ(base.c, 0.0);
}

/// fault_device turning to `fault` (nan, huge) after 200 reads, with sim_is900 and
/// fault_base, both logging their commands; the run's report and the scene's line.
struct DeviceFaultRun {
  ServerReport report;
  fs::path file, device_log, base_log;
  int device_line = 0;
};

DeviceFaultRun run_device_fault(const std::string& fault) {
  DeviceFaultRun run;
  const fs::path dir = temp_dir();
  run.device_log = dir / "device.log";
  run.base_log = dir / "base.log";
  run.file = write_scene(dir, fmt::format(R"(
    <plugin kind="device" name="fault_device">
      <param name="fail_after_reads" value="200"/>
      <param name="fault" value="{}"/>
      <param name="command_log" value="{}"/>
    </plugin>
    <plugin kind="tracker" name="sim_is900"/>
    <plugin kind="base" name="fault_base">
      <param name="command_log" value="{}"/>
    </plugin>)", fault, run.device_log.string(), run.base_log.string()));
  run.device_line = scene_line_of(run.file, "name=\"fault_device\"");
  Loaded l = load(run.file);
  if (!l.scene) {
    ADD_FAILURE() << "scene did not load";
    return run;
  }
  auto build = HapticServer::open(*l.description, *l.scene, options_for(30.0));
  if (!build.ok()) {
    ADD_FAILURE() << "server did not open";
    return run;
  }
  run.report = build->server->run();
  return run;
}

TEST(HapticServer, DeviceReturningNanEndsTheRunWithZeroForceAndTheBaseStopped) {
  const DeviceFaultRun run = run_device_fault("nan");
  ASSERT_TRUE(run.report.error);
  EXPECT_EQ(*run.report.error, fmt::format("{}:{}: error: plugin 'fault_device': device_read returned a non-finite "
                                           "p_D_tool_m[1]",
                                           run.file.string(), run.device_line));
  expect_safe_stop_after(run.report, run.device_log, run.base_log);
  EXPECT_GT(read_log(run.device_log).count, 1u);
}

TEST(HapticServer, AToolAt1e30MetresIsAFaultNamingTheDevice) {
  const DeviceFaultRun run = run_device_fault("huge");
  ASSERT_TRUE(run.report.error);
  EXPECT_EQ(*run.report.error, fmt::format("{}:{}: error: plugin 'fault_device': device_read returned the tool at "
                                           "(0, 1e+30, 0.0322719) m, outside the device's workspace by more than 0.1 m",
                                           run.file.string(), run.device_line));
  expect_safe_stop_after(run.report, run.device_log, run.base_log);
}

TEST(HapticServer, ABaseTracked1e9MetresAwayIsAFaultNamingTheTracker) {
  const fs::path dir = temp_dir();
  const fs::path device_log = dir / "device.log", base_log = dir / "base.log";
  const fs::path file = write_scene(dir, fmt::format(R"(
    <plugin kind="device" name="fault_device">
      <param name="command_log" value="{}"/>
    </plugin>
    <plugin kind="tracker" name="fault_tracker">
      <param name="pose" value="1e9 0 0 1 0 0 0"/>
    </plugin>
    <plugin kind="base" name="fault_base">
      <param name="command_log" value="{}"/>
    </plugin>)", device_log.string(), base_log.string()));
  Loaded l = load(file);
  ASSERT_TRUE(l.scene);
  auto build = HapticServer::open(*l.description, *l.scene, options_for(30.0));
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  ASSERT_TRUE(r.error);
  EXPECT_EQ(*r.error, fmt::format("{}:{}: error: plugin 'fault_tracker': tracker_read returned sensor 0 at 1e+09 m "
                                  "from the tracker, beyond its tracking range of 50 m",
                                  file.string(), scene_line_of(file, "name=\"fault_tracker\"")));
  expect_safe_stop_after(r, device_log, base_log);
}

TEST(HapticServer, DeviceErrorAndDeactivateEndTheRunNamingThePlugin) {
  for (const std::string fault : {"error", "deactivate"}) {
    const fs::path dir = temp_dir() / fault;
    fs::create_directories(dir);
    const fs::path device_log = dir / "device.log";
    const fs::path file = write_scene(dir, fmt::format(R"(
    <plugin kind="device" name="fault_device">
      <param name="fail_after_reads" value="100"/>
      <param name="fault" value="{}"/>
      <param name="command_log" value="{}"/>
    </plugin>
    <plugin kind="tracker" name="sim_is900"/>)", fault, device_log.string()));
    Loaded l = load(file);
    ASSERT_TRUE(l.scene);
    auto build = HapticServer::open(*l.description, *l.scene, options_for(30.0));
    ASSERT_TRUE(build.ok());
    const ServerReport r = build->server->run();
    ASSERT_TRUE(r.error) << fault;
    const std::string where = fmt::format("{}:{}: error: plugin 'fault_device'", file.string(),
                                          scene_line_of(file, "name=\"fault_device\""));
    EXPECT_THAT(*r.error, HasSubstr(where));
    EXPECT_THAT(*r.error, HasSubstr(fault == "error" ? "injected fault: hardware not responding"
                                                     : "device_read asked to be stopped"));
    EXPECT_TRUE(r.zero_force_sent);
    const CommandLog device = read_log(device_log);
    EXPECT_EQ(device.a, 0.0);
    EXPECT_EQ(device.b, 0.0);
    EXPECT_EQ(device.c, 0.0);
  }
}

TEST(HapticServer, BaseFailingMidRunStopsTheBaseAndZeroesTheForce) {
  const fs::path dir = temp_dir();
  const fs::path device_log = dir / "device.log", base_log = dir / "base.log";
  const fs::path file = write_scene(dir, fmt::format(R"(
    <plugin kind="device" name="fault_device">
      <param name="command_log" value="{}"/>
    </plugin>
    <plugin kind="tracker" name="sim_is900"/>
    <plugin kind="base" name="fault_base">
      <param name="fail_after_reads" value="300"/>
      <param name="fault" value="error"/>
      <param name="command_log" value="{}"/>
    </plugin>)", device_log.string(), base_log.string()));
  Loaded l = load(file);
  ASSERT_TRUE(l.scene);
  auto build = HapticServer::open(*l.description, *l.scene, options_for(30.0));
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  ASSERT_TRUE(r.error);
  EXPECT_THAT(*r.error, HasSubstr(fmt::format("{}:{}: error: plugin 'fault_base': ", file.string(),
                                              scene_line_of(file, "name=\"fault_base\""))));
  EXPECT_THAT(*r.error, HasSubstr("injected fault: hardware not responding"));
  EXPECT_TRUE(r.zero_force_sent);
  EXPECT_TRUE(r.base_stop_sent);
  EXPECT_EQ(read_log(device_log).b, 0.0);
  const CommandLog base = read_log(base_log);
  EXPECT_GT(base.count, 0u);
  EXPECT_EQ(base.a, 0.0);
  EXPECT_EQ(base.c, 0.0);
}

TEST(HapticServer, SilentTrackerFadesForceOutAndStopsTheBase) {
  const fs::path dir = temp_dir();
  // A replay log with the base sensor at its nominal pose for 0.4 s, then nothing.
  const auto rig_read = read_scene_file(std::string(MHD_SOURCE_DIR) + "/scenes/rigs/pomhi.xml");
  const Rig rig = Rig::from_scene(*rig_read).value();
  const Pose X = rig.X_is900_base_sensor_from_base({});
  const Eigen::Quaterniond q(X.rotation());
  const fs::path replay = dir / "tracker.csv";
  {
    std::ofstream out(replay);
    out << "timestamp_s,sensor_id,sequence,px,py,pz,qw,qx,qy,qz\n";
    for (int i = 0; i < 40; ++i) {
      out << fmt::format("{:.3f},0,{},{:.9f},{:.9f},{:.9f},{:.12f},{:.12f},{:.12f},{:.12f}\n", 0.01 * i, i + 1,
                         X.translation().x(), X.translation().y(), X.translation().z(), q.w(), q.x(), q.y(), q.z());
    }
  }
  const fs::path base_log = dir / "base.log";
  const fs::path file = write_scene(dir, fmt::format(R"(
    <plugin kind="device" name="fault_device"/>
    <plugin kind="tracker" name="replay">
      <param name="file" value="{}"/>
    </plugin>
    <plugin kind="base" name="fault_base">
      <param name="command_log" value="{}"/>
    </plugin>)", replay.string(), base_log.string()), R"(
  <server>
    <param name="fade_in_s" value="0.1"/>
  </server>)");
  Loaded l = load(file);
  ASSERT_TRUE(l.scene);
  ServerOptions o = options_for(1.0);
  o.recording = dir / "run.csv";
  o.plan_base = [](const BasePlanInput&) { return BaseTwist{0.1, 0.0, 0.0}; };  // keeps asking to move
  auto build = HapticServer::open(*l.description, *l.scene, o);
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_GT(r.stale_ticks, 0u);
  EXPECT_GT(r.base_stops, 0u);
  const CommandLog base = read_log(base_log);
  EXPECT_EQ(base.a, 0.0);  // the planner still asks for 0.1 m/s; the guard stopped the base

  // In the recording: full gain while samples flow, zero force from the timeout on.
  std::ifstream csv(o.recording);
  std::string line;
  std::getline(csv, line);
  std::size_t rows_fresh_full = 0, rows_stale = 0, stale_with_force = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 31u);
    const double age = std::stod(cells[26]), gain = std::stod(cells[27]);
    const double fx = std::stod(cells[11]), fy = std::stod(cells[12]), fz = std::stod(cells[13]);
    if (age >= 0.05) {
      ++rows_stale;
      if (fx != 0.0 || fy != 0.0 || fz != 0.0 || gain != 0.0) ++stale_with_force;
    } else if (age >= 0.0 && age < 0.02 && gain == 1.0) {
      ++rows_fresh_full;
    }
  }
  EXPECT_GT(rows_fresh_full, 0u);
  EXPECT_GT(rows_stale, 100u);
  EXPECT_EQ(stale_with_force, 0u);
}

/// fault_tracker's pose param: the base sensor where the rig puts it with the base at the origin.
std::string nominal_base_sensor_pose() {
  const auto rig_read = read_scene_file(std::string(MHD_SOURCE_DIR) + "/scenes/rigs/pomhi.xml");
  const Rig rig = Rig::from_scene(*rig_read).value();
  const Pose X = rig.X_is900_base_sensor_from_base({});
  const Eigen::Quaterniond q(X.rotation());
  return fmt::format("{:.12f} {:.12f} {:.12f} {:.15f} {:.15f} {:.15f} {:.15f}", X.translation().x(),
                     X.translation().y(), X.translation().z(), q.w(), q.x(), q.y(), q.z());
}

TEST(HapticServer, ADeviceCallThatBlocksTooLongEndsTheRunAndStopsTheBase) {
  const fs::path dir = temp_dir();
  const fs::path device_log = dir / "device.log", base_log = dir / "base.log";
  const fs::path file = write_scene(dir, fmt::format(R"(
    <plugin kind="device" name="fault_device">
      <param name="fail_after_reads" value="300"/>
      <param name="fault" value="block"/>
      <param name="block_s" value="0.5"/>
      <param name="command_log" value="{}"/>
    </plugin>
    <plugin kind="tracker" name="sim_is900"/>
    <plugin kind="base" name="fault_base">
      <param name="command_log" value="{}"/>
    </plugin>)", device_log.string(), base_log.string()));
  Loaded l = load(file);
  ASSERT_TRUE(l.scene);
  ServerOptions o = options_for(30.0);
  o.plan_base = [](const BasePlanInput&) { return BaseTwist{0.1, 0.0, 0.0}; };  // keeps asking to move
  auto build = HapticServer::open(*l.description, *l.scene, o);
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.ended_by, RunEnd::Fault);
  EXPECT_THAT(*r.error, HasSubstr(fmt::format("{}:{}: error: plugin 'fault_device': device_read has not returned after ",
                                              file.string(), scene_line_of(file, "name=\"fault_device\""))));
  EXPECT_THAT(*r.error, HasSubstr("ms (plugin_call_timeout_s); the run ends"));
  EXPECT_TRUE(r.base_stop_sent);
  const CommandLog base = read_log(base_log);
  EXPECT_GT(base.count, 0u);
  EXPECT_EQ(base.a, 0.0);
  // Once the call came back, the haptic thread left the device with zero torque.
  EXPECT_TRUE(r.zero_force_sent);
  const CommandLog device = read_log(device_log);
  EXPECT_EQ(device.a, 0.0);
  EXPECT_EQ(device.b, 0.0);
  EXPECT_EQ(device.c, 0.0);
}

/// How a run went, for a failed expectation on it: how it ended and what the threads did.
std::string run_summary(const ServerReport& r) {
  const char* ended = r.ended_by == RunEnd::Duration ? "duration" : r.ended_by == RunEnd::StopRequested ? "stop" : "fault";
  return fmt::format("ended by {} after {:.2f} s: {} ticks ({} before the first pose, {} stale, {} faulty, {} missed "
                     "deadlines), {} tracker samples ({} rejected, last {:.3f} s old), {} base commands; error: {}",
                     ended, r.status.elapsed_s, r.status.ticks, r.startup_ticks, r.stale_ticks, r.fault_ticks,
                     r.missed_deadlines, r.status.tracker_samples, r.status.tracker_rejected, r.status.tracker_age_s,
                     r.base_commands, r.error.value_or("none"));
}

TEST(HapticServer, ATrackerStuckInACallEndsTheRunWithTheBaseStopped) {
  const fs::path dir = temp_dir();
  const fs::path device_log = dir / "device.log", base_log = dir / "base.log";
  const fs::path file = write_scene(dir, fmt::format(R"(
    <plugin kind="device" name="fault_device">
      <param name="command_log" value="{}"/>
    </plugin>
    <plugin kind="tracker" name="fault_tracker">
      <param name="pose" value="{}"/>
      <param name="fail_after_reads" value="300"/>
      <param name="fault" value="block"/>
      <param name="block_s" value="0.6"/>
    </plugin>
    <plugin kind="base" name="fault_base">
      <param name="command_log" value="{}"/>
    </plugin>)", device_log.string(), nominal_base_sensor_pose(), base_log.string()));
  Loaded l = load(file);
  ASSERT_TRUE(l.scene);
  ServerOptions o = options_for(30.0);
  o.plan_base = [](const BasePlanInput&) { return BaseTwist{0.1, 0.0, 0.0}; };
  auto build = HapticServer::open(*l.description, *l.scene, o);
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  // The 300 reads take about 0.3 s at the io thread's 1 kHz, and the next read blocks
  // 0.6 s, six times the call timeout: the run ends well before its 30 s.
  ASSERT_TRUE(r.error) << run_summary(r);
  EXPECT_THAT(*r.error, HasSubstr(fmt::format("{}:{}: error: plugin 'fault_tracker': tracker_read has not returned after ",
                                              file.string(), scene_line_of(file, "name=\"fault_tracker\""))));
  EXPECT_TRUE(r.base_stop_sent);
  EXPECT_EQ(read_log(base_log).a, 0.0);
  EXPECT_TRUE(r.zero_force_sent);
  EXPECT_EQ(read_log(device_log).b, 0.0);
  EXPECT_GT(r.base_commands, 0u);  // it was moving before
}

TEST(HapticServer, OpenReportsEveryProblemAtItsSceneLine) {
  const fs::path dir = temp_dir();
  const fs::path file = write_scene(dir, R"(
    <plugin kind="device" name="no_such_device"/>
    <plugin kind="base" name="fault_base"/>
    <plugin kind="base" name="fault_base"/>)", R"(
  <server>
    <param name="tracker_timeout_ms" value="50"/>
  </server>)");
  Loaded l = load(file);
  ASSERT_TRUE(l.scene);
  auto build = HapticServer::open(*l.description, *l.scene, options_for(1.0));
  EXPECT_FALSE(build.ok());
  std::vector<std::string> messages;
  for (const auto& d : build.diagnostics()) messages.push_back(d.to_string());
  const std::string f = file.string();
  EXPECT_THAT(messages, ::testing::Contains(HasSubstr(fmt::format(
                            "{}:{}: error: unknown param 'tracker_timeout_ms' in <server>", f,
                            scene_line_of(file, "tracker_timeout_ms")))));
  EXPECT_THAT(messages, ::testing::Contains(HasSubstr(fmt::format(
                            "{}:{}: error: a second base plugin 'fault_base'", f,
                            scene_line_of(file, "name=\"fault_base\"") + 1))));
  EXPECT_THAT(messages, ::testing::Contains(HasSubstr(fmt::format(
                            "{}:{}: error: the scene names no tracker plugin (<plugin kind=\"tracker\">), which a "
                            "mobile rig needs",
                            f, scene_line_of(file, "<plugins>")))));
}

TEST(HapticServer, AMissingPluginIsAnErrorAtItsLineAndNothingRuns) {
  const fs::path dir = temp_dir();
  const fs::path file = write_scene(dir, R"(
    <plugin kind="device" name="no_such_device"/>
    <plugin kind="tracker" name="sim_is900"/>)");
  Loaded l = load(file);
  ASSERT_TRUE(l.scene);
  auto build = HapticServer::open(*l.description, *l.scene, options_for(1.0));
  EXPECT_FALSE(build.ok());
  ASSERT_EQ(build.diagnostics().size(), 1u);
  EXPECT_THAT(build.diagnostics()[0].to_string(),
              HasSubstr(fmt::format("{}:{}: error: plugin 'no_such_device'", file.string(),
                                    scene_line_of(file, "no_such_device"))));
}

// A desktop rig sharing a box (id 1, rigs 1 2) as rig 2, with fault_device (logging its
// commands) and fault_link playing rig 1's states of the box, given `link_params`.
fs::path write_shared_scene(const fs::path& dir, const fs::path& device_log, const std::string& link_params) {
  const fs::path file = dir / "shared.xml";
  std::ofstream(file) << fmt::format(R"(<?xml version="1.0"?>
<scene version="1" unit="m">
  <rig kind="desktop">
    <frame name="device" parent="world" position="0 0.5 0" rpy_deg="0 0 0"/>
  </rig>
  <object name="box">
    <material stiffness_N_per_m="1000"/>
    <box size="0.1 0.1 0.1"/>
    <pose position="0 0.05 -0.5"/>
    <dynamics mass_kg="1"/>
  </object>
  <sharing rig_id="2">
    <shared_object object="box" id="1" rigs="1 2"/>
  </sharing>
  <plugins>
    <plugin kind="device" name="fault_device">
      <param name="command_log" value="{}"/>
    </plugin>
    <plugin kind="link" name="fault_link">
      <param name="start_m" value="0 0.05 -0.5"/>
      <param name="velocity_mps" value="0.1 0 0"/>
{}
    </plugin>
  </plugins>
  <server>
    <param name="plugin_call_timeout_s" value="0.2"/>
  </server>
</scene>
)", device_log.string(), link_params);
  return file;
}

TEST(HapticServer, AReplicaFollowsTheStatesItsLinkBrings) {
  const fs::path dir = temp_dir();
  const fs::path file = write_shared_scene(dir, dir / "device.log", "");
  Loaded l = load(file);
  ASSERT_TRUE(l.scene);
  auto build = HapticServer::open(*l.description, *l.scene, options_for(1.5));
  for (const auto& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_EQ(r.ended_by, RunEnd::Duration);
  ASSERT_EQ(r.shared_objects.size(), 1u);
  const SharedObjectEnd& box = r.shared_objects[0];
  EXPECT_EQ(box.name, "box");
  EXPECT_EQ(box.id, 1u);
  EXPECT_EQ(box.authority_rig, 1u);
  EXPECT_FALSE(box.held_here);
  EXPECT_EQ(box.p_W_start_m, Eigen::Vector3d(0.0, 0.05, -0.5));
  // 1.5 s at 0.1 m/s along x, as the link said (the link started a little before the run).
  EXPECT_NEAR(box.p_W_end_m.x(), 0.15, 0.03);
  EXPECT_NEAR(box.p_W_end_m.y(), 0.05, 1e-9);
  EXPECT_NEAR(box.p_W_end_m.z(), -0.5, 1e-9);
  EXPECT_LT(box.state_age_s, 0.05);
  EXPECT_GT(r.sharing.states_obeyed, 500u);
  EXPECT_EQ(r.sharing.states_ignored, 0u);
  EXPECT_EQ(r.sharing.states_sent, 0u);  // a replica sends no state
  EXPECT_EQ(r.link_dropped, 0u);
  EXPECT_TRUE(r.zero_force_sent);
}

TEST(HapticServer, ALinkThatFailsEndsTheRunWithZeroForceNamingIt) {
  const struct {
    const char* params;
    const char* error;
  } cases[] = {
      {R"(<param name="fail_after_reads" value="300"/><param name="fault" value="error"/>)",
       "plugin 'fault_link': link_read failed: injected fault: hardware not responding"},
      {R"(<param name="fail_after_reads" value="300"/><param name="fault" value="nan"/>)",
       "plugin 'fault_link': link_read returned a non-finite messages[0].p_W_m[0]"},
      {R"(<param name="fail_after_reads" value="300"/><param name="fault" value="deactivate"/>)",
       "plugin 'fault_link': link_read asked to be stopped (MHD_DEACTIVATE)"},
      {R"(<param name="fail_after_reads" value="300"/><param name="fault" value="block"/><param name="block_s" value="2"/>)",
       "plugin 'fault_link': link_read has not returned after "},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.params);
    const fs::path dir = temp_dir();
    const fs::path device_log = dir / "device.log";
    const fs::path file = write_shared_scene(dir, device_log, c.params);
    Loaded l = load(file);
    ASSERT_TRUE(l.scene);
    auto build = HapticServer::open(*l.description, *l.scene, options_for(30.0));
    ASSERT_TRUE(build.ok());
    const ServerReport r = build->server->run();
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.ended_by, RunEnd::Fault);
    EXPECT_THAT(*r.error, HasSubstr(fmt::format("{}:{}: error: {}", file.string(),
                                                scene_line_of(file, "name=\"fault_link\""), c.error)));
    EXPECT_TRUE(r.zero_force_sent);
    const CommandLog device = read_log(device_log);
    EXPECT_GT(device.count, 100u);
    EXPECT_EQ(device.a, 0.0);
    EXPECT_EQ(device.b, 0.0);
    EXPECT_EQ(device.c, 0.0);
  }
}

}  // namespace
