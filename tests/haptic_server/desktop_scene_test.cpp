// The desktop scenes through the server with their real plugins
// (docs/desktop.md): a device and nothing else. The seated simulated user strokes the
// bunny: forces are rendered in contact and stay below the device's limit, free space gets
// zero force, and the recorded proxy never crosses the surface (the exact oracle of
// tools/verification on every leg of every tick, as the proxy tests use it). No tracker, base or planner runs.
#include "haptic_server/haptic_server.h"

#include "haptic_server/haptic_tick.h"
#include "kinematics/rig.h"
#include "recording/csv_recording_reader.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "verification/proxy_drive.h"
#include "verification/surface_crossing_oracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace mhd {
namespace {

namespace fs = std::filesystem;

Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

struct DesktopRun {
  ServerReport report;
  std::vector<RecordingRow> rows;
  std::optional<SceneDescription> description;
  std::optional<CompiledScene> scene;
};

DesktopRun run_scene(const std::string& name, double duration_s) {
  DesktopRun out;
  const Result<SceneDescription> read = read_scene_file(std::string(MHD_SOURCE_DIR) + "/scenes/" + name + ".xml");
  for (const auto& d : read.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!read.ok()) return out;
  EXPECT_EQ(read->rig_kind.kind, RigKind::Desktop);
  Result<std::unique_ptr<CompiledScene>> compiled = compile_scene(*read);
  for (const auto& d : compiled.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!compiled.ok()) return out;
  out.scene = std::move(*compiled.value());
  out.description = *read;

  const fs::path dir = fs::path(::testing::TempDir()) / "desktop_scene_test";
  fs::create_directories(dir);
  ServerOptions o;
  o.duration_s = duration_s;
  o.recording = dir / (name + ".csv");
  auto build = HapticServer::open(*read, *out.scene, o);
  for (const auto& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!build.ok()) return out;
  out.report = build->server->run();
  const Result<std::vector<RecordingRow>> recording = read_recording(o.recording);
  EXPECT_TRUE(recording.ok());
  out.rows = recording.value();
  return out;
}

/// The recorded run's proxy path with every leg of every tick (ProxyState::path_W): the
/// recording again through HapticTick, which must give the recorded proxy exactly; from the
/// first tick the proxy ran (before it, a hand that starts inside an object has it wait).
verify::TickRecord proxy_path(const DesktopRun& run) {
  verify::TickRecord record;
  const Result<Rig, std::vector<RigError>> rig = Rig::from_scene(*run.description);
  EXPECT_TRUE(rig.ok());
  if (!rig.ok()) return record;
  HapticTick tick(*run.scene, *rig, HapticTickSettings{});
  for (const RecordingRow& row : run.rows) {
    const HapticTickOutput out = tick.render(row.t_s, row.dt_s, vec(row.p_D_tool_m), BasePose{}, HapticTick::kNoTracker);
    EXPECT_EQ(out.proxy_W_m, vec(row.proxy_W_m)) << "replayed at t = " << row.t_s;
    const ProxyState& state = tick.proxy_state();
    if (!state.initialised) continue;
    verify::TickSample s;
    s.p_W_hip = out.p_W_hip;
    s.proxy_W = out.proxy_W_m;
    s.force_W = out.proxy_force_W_N;
    s.in_contact = out.in_contact;
    s.path_points = state.path_points;
    s.path_W = state.path_W;
    record.push_back(s);
  }
  return record;
}

void expect_desktop_strokes(const std::string& name, double device_limit_N) {
  const DesktopRun run = run_scene(name, 3.0);
  ASSERT_TRUE(run.scene);
  const ServerReport& r = run.report;
  ASSERT_FALSE(r.error) << *r.error;
  EXPECT_EQ(r.ended_by, RunEnd::Duration);
  EXPECT_EQ(r.status.rig_kind, RigKind::Desktop);
  // The device is the whole pose: no start-up wait, nothing stale, no tracker, no base.
  EXPECT_EQ(r.startup_ticks, 0u);
  EXPECT_EQ(r.stale_ticks, 0u);
  EXPECT_EQ(r.fault_ticks, 0u);
  EXPECT_EQ(r.status.tracker_samples, 0u);
  EXPECT_EQ(r.base_commands, 0u);
  EXPECT_TRUE(r.zero_force_sent);
  EXPECT_GT(r.contact_ticks, 200u) << "the hand should stroke the bunny";
  EXPECT_EQ(r.recording_rows, r.status.ticks);
  ASSERT_EQ(run.rows.size(), r.recording_rows);

  std::size_t touching = 0, free = 0;
  double max_force_N = 0.0;
  for (const RecordingRow& row : run.rows) {
    // Same columns as a mobile recording; those of the tracker and the base are empty.
    EXPECT_TRUE(std::isnan(row.base_x_m) && std::isnan(row.base_heading_rad));
    EXPECT_EQ(row.tracker_age_s, -1.0);
    ASSERT_TRUE(vec(row.p_W_hip).allFinite());
    const double force_N = vec(row.force_W_N).norm();
    max_force_N = std::max(max_force_N, force_N);
    if (row.contact != 0) {
      if (force_N > 0.05) ++touching;
    } else {
      ++free;
      EXPECT_EQ(force_N, 0.0) << "free space at t = " << row.t_s;
    }
  }
  EXPECT_GT(touching, r.contact_ticks / 2) << "contact should push";
  EXPECT_GT(free, 100u) << "the stroke should leave the surface too";
  EXPECT_LT(max_force_N, device_limit_N);
  EXPECT_EQ(r.clamped_ticks, 0u);

  const verify::SurfaceCrossingOracle oracle(run.scene->world);
  const verify::TickRecord record = proxy_path(run);
  EXPECT_GT(record.size(), run.rows.size() / 2);
  const std::vector<verify::Crossing> crossings = verify::find_crossings(oracle, record);
  for (const verify::Crossing& c : crossings) {
    ADD_FAILURE() << "the proxy crossed the surface at tick " << c.tick << ": (" << c.from_W.transpose() << ") -> ("
                  << c.to_W.transpose() << "), object " << c.first_hit.where.object << " triangle "
                  << c.first_hit.where.triangle << ", hip (" << record[c.tick].p_W_hip.transpose() << ")";
  }
  EXPECT_EQ(verify::count_ticks_inside(oracle, record), 0u);
}

TEST(DesktopScene, PhantomStrokesTheBunnyWithoutPopThroughAndZeroForceInFreeSpace) {
  expect_desktop_strokes("desktop_bunny", 8.5);
}

TEST(DesktopScene, DeltaStrokesTheBunnyWithoutPopThroughAndZeroForceInFreeSpace) {
  expect_desktop_strokes("desktop_bunny_delta", 8.5);  // the scene's clamp; the delta's own is 9 N
}

}  // namespace
}  // namespace mhd
