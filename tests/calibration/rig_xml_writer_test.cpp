// The calibrated rig XML (engine/calibration/rig_xml_writer.h): it reads back through the
// scene reader and Rig::from_scene, predicts what the calibration predicts, keeps the base
// on the floor, and nothing is written on failure.

#include "calibration/rig_xml_writer.h"
#include "calibration/sample_synthesis.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <unistd.h>

namespace mhd {
namespace {

namespace fs = std::filesystem;

const fs::path kSource(MHD_SOURCE_DIR);

struct Loaded {
  SceneDescription scene;
  Rig rig;
};

Loaded load(const fs::path& file) {
  Result<SceneDescription> read = read_scene_file(file);
  EXPECT_TRUE(read.ok()) << (read.diagnostics().empty() ? "" : read.diagnostics()[0].to_string());
  const Result<Rig, std::vector<RigError>> built = Rig::from_scene(*read);
  EXPECT_TRUE(built.ok()) << built.error_text();
  return {*read, *built};
}

std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

class RigXmlWriter : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mhd_rig_xml_writer_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

RigOffsets some_offsets() {
  RigOffsets o = thesis_calibrated_offsets();
  o.psi_rad = 1.234 * std::numbers::pi / 180.0;
  return o;
}

void expect_same_hips(const Rig& calibrated, const Rig& original, const RigOffsets& offsets) {
  SynthesisOptions options;
  options.samples = 30;
  for (const CalibrationSample& s : synthesize_samples(original, options)) {
    const Eigen::Vector3d from_file =
        calibrated.p_W_hip(calibrated.X_W_robot_from_sensor(s.X_is900_base_sensor), s.q_rad);
    EXPECT_LT((from_file - predicted_p_W_hip(original, offsets, s.X_is900_base_sensor, s.q_rad)).norm(), 1e-6);
  }
}

TEST_F(RigXmlWriter, CalibratedPomhiReadsBackAndPredictsTheSameHip) {
  const fs::path input = kSource / "scenes/rigs/pomhi.xml";
  const std::string before = slurp(input);
  const Loaded original = load(input);
  const RigOffsets offsets = some_offsets();
  const fs::path output = dir_ / "pomhi.calibrated.xml";
  const Result<WrittenRig, std::string> written =
      write_calibrated_rig(original.scene, original.rig, offsets, output, {"from test samples", "psi = 1.234 deg"});
  ASSERT_TRUE(written.ok()) << written.error_text();
  EXPECT_EQ(written->frames_file, input.string());
  EXPECT_EQ(slurp(input), before) << "the input is never touched";
  EXPECT_FALSE(fs::exists(output.string() + ".tmp"));

  const Loaded calibrated = load(output);  // base level and on the floor, or from_scene fails
  expect_same_hips(calibrated.rig, original.rig, offsets);
  EXPECT_TRUE(calibrated.rig.X_base_sensor_robot().translation().isApprox(offsets.p_S_robot_m, 1e-9));
  EXPECT_TRUE(calibrated.rig.X_robot_phantom().translation().isApprox(offsets.p_R_phantom_m, 1e-9));
  // The base frame moves up with SRz (-17.6 mm): 810.8 - 17.6 below the robot.
  EXPECT_NEAR(calibrated.rig.X_robot_base().translation().z(), -0.7932, 1e-9);
  // The planar path and the tracker path still agree.
  const BasePose base{0.4, -0.3, 2.0};
  const Pose X_is900_S = calibrated.rig.X_is900_base_sensor_from_base(base);
  const BasePose back = calibrated.rig.base_from_sensor(X_is900_S);
  EXPECT_NEAR(back.x_m, base.x_m, 1e-9);
  EXPECT_NEAR(back.heading_rad, base.heading_rad, 1e-9);

  const std::string text = slurp(output);
  EXPECT_NE(text.find("Calibrated by mhd calibrate"), std::string::npos);
  EXPECT_NE(text.find("psi = 1.234 deg"), std::string::npos);
  EXPECT_NE(text.find("rpy_deg=\"0 0 91.234\""), std::string::npos) << text;
  EXPECT_NE(text.find("position=\"203.1 -1.8 -387.6\""), std::string::npos) << text;
  EXPECT_NE(text.find("position=\"-2.1 -232.8 41.6\""), std::string::npos) << text;
  EXPECT_NE(text.find("Eq. 4.1"), std::string::npos) << "the file's own comments stay";
}

TEST_F(RigXmlWriter, KeepsTheFilesUnitAndQuaternionForm) {
  const Loaded original = load(kSource / "tests/data/calibration/rig_in_metres.xml");
  const RigOffsets offsets = some_offsets();
  const fs::path output = dir_ / "metres.xml";
  const Result<WrittenRig, std::string> written = write_calibrated_rig(original.scene, original.rig, offsets, output, {});
  ASSERT_TRUE(written.ok()) << written.error_text();
  const Loaded calibrated = load(output);
  expect_same_hips(calibrated.rig, original.rig, offsets);
  const std::string text = slurp(output);
  EXPECT_NE(text.find("position=\"0.2031 -0.0018 -0.3876\""), std::string::npos) << text;
  EXPECT_NE(text.find("quaternion_wxyz=\""), std::string::npos);
  EXPECT_EQ(text.find("rpy_deg=\"0 0 91"), std::string::npos) << text;
}

TEST_F(RigXmlWriter, RigFromAnIncludeIsWrittenAsACopyOfThatFile) {
  const Loaded original = load(kSource / "tests/data/calibration/scene_with_rig.xml");
  const RigOffsets offsets = some_offsets();
  const fs::path output = dir_ / "rig.xml";
  const Result<WrittenRig, std::string> written = write_calibrated_rig(original.scene, original.rig, offsets, output, {});
  ASSERT_TRUE(written.ok()) << written.error_text();
  EXPECT_EQ(fs::path(written->frames_file).filename(), "pomhi.xml");
  expect_same_hips(load(output).rig, original.rig, offsets);
}

TEST_F(RigXmlWriter, FramesSplitOverFilesAreRefused) {
  const fs::path input = kSource / "tests/data/calibration/split_rig/main.xml";
  const Loaded original = load(input);
  const fs::path output = dir_ / "split.xml";
  const Result<WrittenRig, std::string> written = write_calibrated_rig(original.scene, original.rig, some_offsets(), output, {});
  ASSERT_FALSE(written.ok());
  EXPECT_NE(written.error().find("must be defined in one file"), std::string::npos) << written.error();
  EXPECT_FALSE(fs::exists(output));
}

TEST_F(RigXmlWriter, UnwritableOutputLeavesNoFile) {
  const Loaded original = load(kSource / "scenes/rigs/pomhi.xml");
  const fs::path output = dir_ / "no_such_dir" / "rig.xml";
  const Result<WrittenRig, std::string> written = write_calibrated_rig(original.scene, original.rig, some_offsets(), output, {});
  ASSERT_FALSE(written.ok());
  EXPECT_NE(written.error().find("cannot write"), std::string::npos) << written.error();
  EXPECT_FALSE(fs::exists(output));
  EXPECT_FALSE(fs::exists(output.string() + ".tmp"));
}

TEST_F(RigXmlWriter, CommentTextCannotBreakTheXml) {
  const Loaded original = load(kSource / "scenes/rigs/pomhi.xml");
  const fs::path output = dir_ / "comment.xml";
  const Result<WrittenRig, std::string> written =
      write_calibrated_rig(original.scene, original.rig, some_offsets(), output, {"samples from a--b.csv -->"});
  ASSERT_TRUE(written.ok()) << written.error_text();
  load(output);
}

}  // namespace
}  // namespace mhd
