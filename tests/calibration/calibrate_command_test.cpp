// `mhd calibrate` (tools/mhd/calibrate_command.cpp) run in-process: synthesize, calibrate,
// the printed summary, the written rig, and the bad-input messages with no rig written.

#include "calibrate_command.h"

#include "scene_xml/scene_reader.h"
#include "kinematics/rig.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const std::string kSource(MHD_SOURCE_DIR);
const std::string kPomhi = kSource + "/scenes/rigs/pomhi.xml";
const std::string kData = kSource + "/tests/data/calibration/";

struct CommandRun {
  int status = 0;
  std::string out;
  std::string err;
};

CommandRun run(std::vector<std::string> args) {
  CLI::App app{"test", "mhd"};
  app.require_subcommand(1);
  add_calibrate_command(app);
  args.insert(args.begin(), "mhd");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  CommandRun r;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::RuntimeError& e) {
    r.status = e.get_exit_code();
  } catch (const CLI::ParseError&) {
    r.status = 2;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  r.out = testing::internal::GetCapturedStdout();
  r.err = testing::internal::GetCapturedStderr();
  return r;
}

class CalibrateCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mhd_calibrate_command_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(CalibrateCommand, SynthesizeThenCalibrateWritesARigThatReadsBack) {
  const std::string samples = path("samples.csv");
  const CommandRun s = run({"calibrate", "--synthesize", samples, "--rig", kPomhi, "--seed", "3", "--samples", "300"});
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_NE(s.out.find("wrote 300 samples to " + samples), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("truth psi = 1.5 deg"), std::string::npos) << s.out;

  const std::string rig = path("rig.xml");
  const std::string residuals = path("residuals.csv");
  const CommandRun c = run({"calibrate", samples, "--rig", kPomhi, "-o", rig, "--residuals", residuals});
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.err, "");
  EXPECT_NE(c.out.find("residual RMSE (mm)        x         y         z       3-D\n  before "), std::string::npos)
      << c.out;
  EXPECT_NE(c.out.find("\n  after "), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("psi (robot yaw about base_sensor z): 1.5"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("wrote " + rig + " (calibrated copy of " + kPomhi + ")"), std::string::npos) << c.out;

  const mhd::Result<mhd::SceneDescription> read = mhd::read_scene_file(rig);
  ASSERT_TRUE(read.ok());
  EXPECT_TRUE(mhd::Rig::from_scene(*read).ok());

  std::ifstream in(residuals);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "line,base_x_m,base_z_m,base_heading_rad,before_x_m,before_y_m,before_z_m,after_x_m,after_y_m,after_z_m");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 300);
}

TEST_F(CalibrateCommand, DefaultOutputSitsNextToTheRig) {
  fs::copy_file(kPomhi, path("pomhi.xml"));
  const CommandRun c = run({"calibrate", kData + "synthetic_100.csv", "--rig", path("pomhi.xml")});
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_TRUE(fs::exists(path("pomhi.calibrated.xml")));
}

TEST_F(CalibrateCommand, NanNamesTheLineAndWritesNoRig) {
  const std::string rig = path("rig.xml");
  const CommandRun c = run({"calibrate", kData + "bad_nan.csv", "--rig", kPomhi, "-o", rig});
  EXPECT_EQ(c.status, 1);
  EXPECT_EQ(c.err, "mhd calibrate: error: " + kData + "bad_nan.csv:5: column 'hip_y_m' is not finite (nan)\n");
  EXPECT_FALSE(fs::exists(rig));
}

TEST_F(CalibrateCommand, MissingColumnNamesTheHeader) {
  const std::string rig = path("rig.xml");
  const CommandRun c = run({"calibrate", kData + "missing_column.csv", "--rig", kPomhi, "-o", rig});
  EXPECT_EQ(c.status, 1);
  EXPECT_EQ(c.err.rfind("mhd calibrate: error: " + kData + "missing_column.csv:1: missing column 'theta3_rad'", 0), 0U)
      << c.err;
  EXPECT_FALSE(fs::exists(rig));
}

TEST_F(CalibrateCommand, TooFewSamples) {
  const std::string rig = path("rig.xml");
  const CommandRun c = run({"calibrate", kData + "too_few.csv", "--rig", kPomhi, "-o", rig});
  EXPECT_EQ(c.status, 1);
  EXPECT_EQ(c.err, "mhd calibrate: error: " + kData +
                       "too_few.csv: 5 samples; calibration needs at least 10; no rig written\n");
  EXPECT_FALSE(fs::exists(rig));
}

TEST_F(CalibrateCommand, SameJointAnglesNamePsi) {
  const std::string rig = path("rig.xml");
  const CommandRun c = run({"calibrate", kData + "same_joint_angles.csv", "--rig", kPomhi, "-o", rig});
  EXPECT_EQ(c.status, 1);
  EXPECT_EQ(c.err.rfind("mhd calibrate: error: " + kData +
                            "same_joint_angles.csv: the samples leave psi (the robot's yaw about base_sensor z) "
                            "unobservable",
                        0),
            0U)
      << c.err;
  EXPECT_NE(c.err.find("no rig written"), std::string::npos);
  EXPECT_FALSE(fs::exists(rig));
}

TEST_F(CalibrateCommand, BadRigIsReported) {
  const CommandRun c = run({"calibrate", kData + "synthetic_100.csv", "--rig", kData + "no_such_rig.xml", "-o", path("r.xml")});
  EXPECT_EQ(c.status, 1);
  EXPECT_EQ(c.err.rfind("mhd calibrate: error: " + kData + "no_such_rig.xml: scene file", 0), 0U) << c.err;
}

TEST_F(CalibrateCommand, UsageErrors) {
  EXPECT_EQ(run({"calibrate", kData + "synthetic_100.csv"}).status, 2);  // no --rig
  EXPECT_EQ(run({"calibrate", kData + "synthetic_100.csv", "--rig", kPomhi, "--split", "half"}).status, 2);
  EXPECT_EQ(run({"calibrate", "x.csv", "--rig", kPomhi, "--synthesize", "--sr-mm", "1,2"}).status, 2);
}

TEST_F(CalibrateCommand, NoPsiKeepsTheRobotsRotation) {
  const std::string rig = path("rig.xml");
  const CommandRun c = run({"calibrate", kData + "synthetic_100.csv", "--rig", kPomhi, "-o", rig, "--no-psi"});
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("psi (robot yaw about base_sensor z): 0.0000 deg"), std::string::npos) << c.out;
  std::ifstream in(rig);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("rpy_deg=\"0 0 90\""), std::string::npos);
}

}  // namespace
