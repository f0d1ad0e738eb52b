// The dolphin demo with the impedance hand: the scene as shipped,
// with the walk-in shortened (the user starts 0.3 m before the dolphin, the base where the
// 20 s demo leaves it) so that a few seconds hold a stroke. The rendered force pushes the
// hand back: forces stay well below the 8.5 N clamp and penetrations are millimetres,
// where the kinematic hand sat at the clamp about 26 mm deep.
#include "haptic_server/haptic_server.h"

#include "recording/csv_recording_reader.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;

double norm(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/// scenes/dolphin.xml with its user's walk shortened, written to `dir` (its relative
/// references made absolute): the simulated plugins read the user from the scene file.
fs::path shortened_dolphin(const fs::path& dir) {
  std::ifstream in(std::string(MHD_SOURCE_DIR) + "/scenes/dolphin.xml");
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const std::string scenes = std::string(MHD_SOURCE_DIR) + "/scenes/";
  for (const std::string relative : {"common/", "rigs/", "../assets/"}) {
    const std::string from = "file=\"" + relative;
    for (std::size_t at = xml.find(from); at != std::string::npos; at = xml.find(from, at + 1)) {
      xml.replace(at, from.size(), "file=\"" + scenes + relative);
    }
  }
  const std::string walk = "value=\"0.05 1.4 0.4; 0.05 -0.2 0.3\"";
  const std::size_t at = xml.find(walk);
  EXPECT_NE(at, std::string::npos) << "dolphin.xml's walk changed";
  if (at != std::string::npos) xml.replace(at, walk.size(), "value=\"0.05 0.1 0.4; 0.05 -0.2 0.3\"");
  const fs::path file = dir / "dolphin_short_walk.xml";
  std::ofstream(file) << xml;
  return file;
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

TEST(ImpedanceHandDemo, StrokesTheDolphinWellBelowTheClampWithMillimetrePenetrations) {
  const fs::path dir = fs::path(::testing::TempDir()) / "impedance_hand_demo";
  fs::create_directories(dir);
  auto read = read_scene_file(shortened_dolphin(dir));
  ASSERT_TRUE(read.ok()) << read.error().front().to_string();
  SceneDescription description = *read;
  for (PluginDescription& p : description.plugins) {
    if (p.name == "sim_phantom") {
      EXPECT_EQ(p.params["hand_model"], "impedance");  // the demo as shipped
    }
    if (p.name == "sim_omni3") p.params = {{"x_m", "-0.16"}, {"z_m", "-0.8"}, {"heading_deg", "0"}};
  }
  ASSERT_TRUE(description.simulated_user);
  ASSERT_EQ(description.simulated_user->params["path"], "0.05 0.1 0.4; 0.05 -0.2 0.3");
  auto compiled = compile_scene(description);
  ASSERT_TRUE(compiled.ok());

  ServerOptions o;
  o.duration_s = 4.0;
  o.recording = dir / "dolphin.csv";
  auto build = HapticServer::open(description, *compiled.value(), o);
  for (const auto& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  ASSERT_TRUE(build.ok());
  const ServerReport r = build->server->run();
  ASSERT_FALSE(r.error) << *r.error;
  EXPECT_EQ(r.clamped_ticks, 0u);
  EXPECT_EQ(r.fault_ticks, 0u);

  const Result<std::vector<RecordingRow>> recording = read_recording(o.recording);
  ASSERT_TRUE(recording.ok());
  std::vector<double> force_N, penetration_m;
  for (const RecordingRow& row : recording.value()) {
    if (row.contact == 0) continue;
    force_N.push_back(norm(row.force_W_N));
    penetration_m.push_back(norm({row.proxy_W_m[0] - row.p_W_hip[0], row.proxy_W_m[1] - row.p_W_hip[1],
                                  row.proxy_W_m[2] - row.p_W_hip[2]}));
  }
  ASSERT_GT(force_N.size(), 1000u) << "the hand should stroke the dolphin for over a second";
  // Ordinary strokes: well below 8.5 N (the kinematic hand: 8.5 N at the 90th percentile).
  EXPECT_LT(quantile(force_N, 0.9), 5.0);
  EXPECT_LT(quantile(force_N, 1.0), 6.5);
  EXPECT_GT(quantile(force_N, 0.5), 0.3);   // and a real touch
  EXPECT_GT(quantile(penetration_m, 0.5), 0.5e-3);
  EXPECT_LT(quantile(penetration_m, 0.9), 10e-3);  // the kinematic hand: 22 mm
  EXPECT_LT(quantile(penetration_m, 1.0), 14e-3);
}

}  // namespace
}  // namespace mhd
