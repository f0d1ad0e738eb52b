// Absurd settings are refused at their file:line, each from its own
// small file under tests/data/scenes/malformed/; every scene the repository ships passes.

#include "scene/plausible_bounds.h"
#include "scene_test_support.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace mhd {
namespace {

using test::to_strings;
using Lines = std::vector<std::string>;

const std::string kMalformedDir = "tests/data/scenes/malformed/";

class PlausibleSettings : public test::FromSourceRoot {
 protected:
  static Lines errors_of(const std::string& name) {
    const Result<SceneDescription> result = read_scene_file(kMalformedDir + name);
    EXPECT_FALSE(result.ok()) << name << " was accepted";
    return to_strings(result.diagnostics());
  }
  static std::string at(const std::string& name, int line, const std::string& message) {
    return kMalformedDir + name + ":" + std::to_string(line) + ": error: " + message;
  }
};

TEST_F(PlausibleSettings, AFiveHertzHapticLoopIsRefused) {
  EXPECT_EQ(errors_of("slow_haptic_rate.xml"),
            (Lines{at("slow_haptic_rate.xml", 3,
                      "attribute 'update_rate_Hz' on <haptics> must be within [500, 20000] Hz, got 5")}));
}

TEST_F(PlausibleSettings, ATinyHapticRateIsRefusedAtItsAttributesLine) {
  EXPECT_EQ(errors_of("tiny_haptic_rate.xml"),
            (Lines{at("tiny_haptic_rate.xml", 4,
                      "attribute 'update_rate_Hz' on <haptics> must be within [500, 20000] Hz, got 1e-308")}));
}

TEST_F(PlausibleSettings, StiffnessAboveWhatTheDeviceRendersStablyIsRefused) {
  EXPECT_EQ(errors_of("absurd_stiffness.xml"),
            (Lines{at("absurd_stiffness.xml", 3,
                      "attribute 'stiffness_N_per_m' on <material> must not exceed 3500 N/m, the stiffest the "
                      "device renders stably at 1000 Hz, got 1e+300"),
                   at("absurd_stiffness.xml", 9,
                      "attribute 'stiffness_N_per_m' on <material> must not exceed 3500 N/m, the stiffest the "
                      "device renders stably at 1000 Hz, got 3501")}));
}

TEST_F(PlausibleSettings, TheStiffnessBoundUsesTheRateWhereverItStands) {
  EXPECT_EQ(errors_of("stiffness_over_rate.xml"),
            (Lines{at("stiffness_over_rate.xml", 4,
                      "attribute 'stiffness_N_per_m' on <material> must not exceed 3500 N/m, the stiffest the "
                      "device renders stably at 1000 Hz, got 6000")}));
}

TEST_F(PlausibleSettings, TheStiffnessBoundScalesWithTheRate) {
  EXPECT_DOUBLE_EQ(max_stable_stiffness_N_per_m(1000.0), 3500.0);
  EXPECT_DOUBLE_EQ(max_stable_stiffness_N_per_m(2000.0), 7000.0);
  EXPECT_DOUBLE_EQ(max_stable_stiffness_N_per_m(500.0), 1750.0);
  const Result<SceneDescription> ok = read_scene_string(R"(<scene version="1">
  <haptics update_rate_Hz="2000"/>
  <object name="ball"><sphere radius="0.1"/><material stiffness_N_per_m="6000"/></object>
</scene>)", "rate_2k.xml");
  EXPECT_TRUE(ok.ok()) << (ok.diagnostics().empty() ? "" : ok.diagnostics().front().to_string());
}

TEST_F(PlausibleSettings, DampingAndFrictionBeyondTheirBoundsAreRefusedButNotAForceLimit) {
  // max_force_N="100" on line 3 is no error: the device's own limit holds at run time, and
  // the scene's can only lower it (docs/haptic_server.md, "Force limit").
  EXPECT_EQ(errors_of("absurd_material.xml"),
            (Lines{at("absurd_material.xml", 4,
                      "attribute 'damping_Ns_per_m' on <material> must not exceed 100 (MHD's bound), got 1000"),
                   at("absurd_material.xml", 5,
                      "attribute 'static_friction' on <material> must not exceed 2 (MHD's bound), got 5"),
                   at("absurd_material.xml", 5,
                      "attribute 'dynamic_friction' on <material> must not exceed 2 (MHD's bound), got 3")}));
}

TEST_F(PlausibleSettings, AShadingCreaseAngleBeyondHundredEightyDegreesIsRefused) {
  EXPECT_EQ(errors_of("absurd_crease_angle.xml"),
            (Lines{at("absurd_crease_angle.xml", 4,
                      "attribute 'shading_crease_deg' on <material> must not exceed 180 (the widest angle two normals "
                      "make), got 270")}));
}

TEST_F(PlausibleSettings, PositionsFartherThanAKilometreAreRefused) {
  EXPECT_EQ(errors_of("far_position.xml"),
            (Lines{at("far_position.xml", 4,
                      "attribute 'position' on <frame> must lie within 1000 m of its frame's origin, got 2000 m"),
                   at("far_position.xml", 9,
                      "attribute 'position' on <pose> must lie within 1000 m of its frame's origin, got 1e+09 m")}));
}

TEST_F(PlausibleSettings, EveryShippedSceneIsPlausible) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const char* dir : {"scenes", "tests/data/scenes/valid", "tests/data/server"}) {
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
      const bool fragment = entry.path().parent_path().filename() == "parts";  // read through an include
      if (entry.is_regular_file() && entry.path().extension() == ".xml" && !fragment) files.push_back(entry.path());
    }
  }
  ASSERT_GT(files.size(), 10u);
  for (const fs::path& file : files) {
    const Result<SceneDescription> result = read_scene_file(file);
    EXPECT_TRUE(result.ok()) << file << ": " << (result.ok() ? "" : result.diagnostics().front().to_string());
  }
}

}  // namespace
}  // namespace mhd
