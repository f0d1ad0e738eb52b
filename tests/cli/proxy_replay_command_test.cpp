// `mhd proxy-replay` (tools/mhd/proxy_replay_command.cpp) run in-process on the cube wall
// with a generated HIP path: a row per input row, the proxy on the HIP with zero force in
// free space, force in contact, identical reruns, and bad input that leaves no file.

#include "proxy_replay_command.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kCubeWall = std::string(MHD_SOURCE_DIR) + "/scenes/cube_wall.xml";
// scenes/cube_wall.xml: the cube's front face lies in z = -0.3 m over x in [-0.2, 0.2] m,
// y in [0.8, 1.2] m; the path pushes into its middle.
constexpr double kWallZ_m = -0.3;
constexpr int kRows = 400;

struct CommandRun {
  int status = 0;
  std::string out;
  std::string err;
};

CommandRun run(std::vector<std::string> args) {
  CLI::App app{"test", "mhd"};
  app.require_subcommand(1);
  add_proxy_replay_command(app);
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

/// A push 20 mm into the wall and back out at 1 kHz: z = -0.26 - 0.06 sin(pi s).
std::string push_path_csv() {
  std::string text = "t_s,x_m,y_m,z_m\n";
  char row[160];
  for (int k = 0; k < kRows; ++k) {
    const double s = static_cast<double>(k) / (kRows - 1);
    const double z = -0.26 - 0.06 * std::sin(std::numbers::pi * s);
    std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g\n", 0.001 * k, 0.01, 1.0, z);
    text += row;
  }
  return text;
}

std::vector<std::vector<double>> read_rows(const std::string& file, std::string& header) {
  std::ifstream in(file);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

std::string text_without_step_us(const std::string& file) {
  std::ifstream in(file);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    // step_us is the next-to-last field.
    const std::size_t last = line.rfind(',');
    const std::size_t before = line.rfind(',', last - 1);
    out += line.substr(0, before) + line.substr(last) + "\n";
  }
  return out;
}

class ProxyReplayCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mhd_proxy_replay_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string p = (dir_ / name).string();
    std::ofstream(p) << text;
    return p;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::size_t files_in_dir() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  fs::path dir_;
};

// Column indices of the ticks CSV.
enum Column { kT, kHipX, kHipY, kHipZ, kProxyX, kProxyY, kProxyZ, kFx, kFy, kFz, kContact, kPlanes, kStepUs, kBudget };

TEST_F(ProxyReplayCommand, PushIntoTheWallAndBack) {
  const std::string hip = write("push.csv", push_path_csv());
  const std::string ticks = path("ticks.csv");
  const CommandRun r = run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", ticks, "--no-cache"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("replayed 400 ticks of " + hip), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote " + ticks), std::string::npos) << r.out;

  std::string header;
  const auto rows = read_rows(ticks, header);
  EXPECT_EQ(header,
            "t_s,hip_x_m,hip_y_m,hip_z_m,proxy_x_m,proxy_y_m,proxy_z_m,force_x_N,force_y_N,force_z_N,contact,planes,"
            "step_us,budget_exhausted");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kRows));
  int free_rows = 0, contact_rows = 0;  // contact_rows: in contact with a force
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& row = rows[k];
    ASSERT_EQ(row.size(), 14u) << "row " << k;
    EXPECT_EQ(row[kT], 0.001 * static_cast<double>(k));
    if (row[kHipZ] > kWallZ_m + 1e-3) {  // clearly in front of the wall: free space
      ++free_rows;
      EXPECT_EQ(row[kProxyX], row[kHipX]) << "row " << k;
      EXPECT_EQ(row[kProxyY], row[kHipY]) << "row " << k;
      EXPECT_EQ(row[kProxyZ], row[kHipZ]) << "row " << k;
      EXPECT_EQ(row[kFx], 0.0) << "row " << k;
      EXPECT_EQ(row[kFy], 0.0) << "row " << k;
      EXPECT_EQ(row[kFz], 0.0) << "row " << k;
      EXPECT_EQ(row[kContact], 0.0) << "row " << k;
    }
    if (row[kContact] == 1.0) {
      // The force pushes the hand back out (+z); damping may cancel it on a fast retreat.
      EXPECT_GE(row[kFz], 0.0) << "row " << k;
      if (row[kFz] > 0.0) ++contact_rows;
      EXPECT_GE(row[kPlanes], 1.0) << "row " << k;
      EXPECT_GE(row[kProxyZ], kWallZ_m) << "row " << k;  // never behind the wall
    }
    EXPECT_GE(row[kStepUs], 0.0);
    EXPECT_TRUE(row[kBudget] == 0.0 || row[kBudget] == 1.0);
  }
  EXPECT_GT(free_rows, 100);
  EXPECT_GT(contact_rows, 50);
  EXPECT_EQ(files_in_dir(), 2u);  // the path and the ticks, no temporary file
}

TEST_F(ProxyReplayCommand, TwoRunsDifferOnlyInStepTime) {
  const std::string hip = write("push.csv", push_path_csv());
  ASSERT_EQ(run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", path("a.csv"), "--no-cache"}).status, 0);
  ASSERT_EQ(run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", path("b.csv"), "--no-cache"}).status, 0);
  const std::string a = text_without_step_us(path("a.csv"));
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, text_without_step_us(path("b.csv")));
}

TEST_F(ProxyReplayCommand, OneRowIsOneTick) {
  const std::string hip = write("one.csv", "t_s,x_m,y_m,z_m\n0.5,0,1,-0.2\n");
  const CommandRun r = run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", path("ticks.csv"), "--no-cache"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  const auto rows = read_rows(path("ticks.csv"), header);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0][kT], 0.5);
  EXPECT_EQ(rows[0][kProxyZ], -0.2);
  EXPECT_EQ(rows[0][kFz], 0.0);
}

TEST_F(ProxyReplayCommand, BadRowIsAnErrorAtItsLineAndLeavesNoFile) {
  std::string text = push_path_csv();
  text += "0.5,0.01,1.0,nan\n";  // line 402
  const std::string hip = write("bad.csv", text);
  const std::string ticks = path("ticks.csv");
  const CommandRun r = run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", ticks, "--no-cache"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "mhd proxy-replay: error: " + hip + ":402: column 'z_m' is not finite (nan)\n");
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(ticks));
  EXPECT_EQ(files_in_dir(), 1u);  // the temporary file is gone too
}

TEST_F(ProxyReplayCommand, TimeGoingBackIsAnError) {
  const std::string hip = write("back.csv", "t_s,x_m,y_m,z_m\n0,0,1,-0.2\n0.002,0,1,-0.2\n0.001,0,1,-0.2\n");
  const CommandRun r = run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", path("t.csv"), "--no-cache"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "mhd proxy-replay: error: " + hip +
                       ":4: column 't_s': 0.001 is not after the previous row's 0.002 (time must increase)\n");
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(ProxyReplayCommand, BadHeaderFailsBeforeTheScene) {
  const std::string hip = write("header.csv", "t,x_m,y_m,z_m\n0,0,1,-0.2\n");
  const CommandRun r = run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", path("t.csv")});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "mhd proxy-replay: error: " + hip +
                       ":1: column 1 is 't', expected 't_s' (the header must be t_s,x_m,y_m,z_m)\n");
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(ProxyReplayCommand, APathStartingInsideTheCubeIsRefused) {
  const std::string hip = write("inside.csv", "t_s,x_m,y_m,z_m\n0,0,1,-0.5\n0.001,0,1,-0.2\n");
  const CommandRun r = run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", path("t.csv"), "--no-cache"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "mhd proxy-replay: error: " + hip + ":2: the first HIP (0, 1, -0.5) m is inside an object in " +
                       kCubeWall + "; the proxy must start in free space\n");
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(ProxyReplayCommand, APathStartingOnTheWallIsRefused) {
  const std::string hip = write("on.csv", "t_s,x_m,y_m,z_m\n0,0,1,-0.3\n");
  const CommandRun r = run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", path("t.csv"), "--no-cache"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(":2: the first HIP (0, 1, -0.3) m "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the proxy must start in free space"), std::string::npos) << r.err;
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(ProxyReplayCommand, MissingPathFile) {
  const CommandRun r =
      run({"proxy-replay", kCubeWall, "--hip-csv", path("none.csv"), "--out", path("t.csv"), "--no-cache"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "mhd proxy-replay: error: " + path("none.csv") + ": HIP path file not found\n");
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(ProxyReplayCommand, AFailedRunLeavesAnEarlierOutputAlone) {
  const std::string ticks = write("ticks.csv", "earlier\n");
  const std::string hip = write("bad.csv", "t_s,x_m,y_m,z_m\n0,0,1,-0.2\n0.001,0,1,abc\n");
  EXPECT_EQ(run({"proxy-replay", kCubeWall, "--hip-csv", hip, "--out", ticks, "--no-cache"}).status, 1);
  std::ifstream in(ticks);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "earlier");
  EXPECT_EQ(files_in_dir(), 2u);
}

}  // namespace
