// A recording replays bit for bit, a changed input shows where it diverges, and a bad
// recording file is refused with its line.
#include "haptic_server/haptic_server.h"
#include "haptic_server/recording_replay.h"
#include "haptic_server/server_settings.h"
#include "recording/csv_recording.h"
#include "recording/csv_recording_reader.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace {

using namespace mhd;
namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "recording_replay_test";
  fs::create_directories(dir);
  return dir / name;
}

class RecordingReplay : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto read = read_scene_file(std::string(MHD_SOURCE_DIR) + "/tests/data/server/touch_box.xml");
    ASSERT_TRUE(read.ok());
    description_ = new SceneDescription(*read);
    auto compiled = compile_scene(*description_);
    ASSERT_TRUE(compiled.ok());
    scene_ = new CompiledScene(std::move(*compiled.value()));
    // ctest runs each case as its own process, perhaps at once: one file per process.
    recording_ = new fs::path(temp_file("touch_box_" + std::to_string(::getpid()) + ".csv"));
    ServerOptions options;
    options.duration_s = 2.5;
    options.recording = *recording_;
    auto build = HapticServer::open(*description_, *scene_, options);
    ASSERT_TRUE(build.ok());
    report_ = new ServerReport(build->server->run());
  }
  static void TearDownTestSuite() {
    delete report_;
    delete recording_;
    delete scene_;
    delete description_;
  }

  static ReplayComparison replay(const std::vector<RecordingRow>& rows) {
    const Rig rig = Rig::from_scene(*description_).value();
    return replay_recording(*scene_, rig, server_settings_from(*description_)->tick, rows);
  }

  static inline SceneDescription* description_ = nullptr;
  static inline CompiledScene* scene_ = nullptr;
  static inline fs::path* recording_ = nullptr;
  static inline ServerReport* report_ = nullptr;
};

TEST_F(RecordingReplay, TheSameInputsGiveTheSameForcesBitForBit) {
  ASSERT_FALSE(report_->error) << *report_->error;
  ASSERT_EQ(report_->recording_dropped, 0u);
  const Result<std::vector<RecordingRow>> read = read_recording(*recording_);
  ASSERT_TRUE(read.ok());
  ASSERT_EQ(read.value().size(), report_->recording_rows);
  std::size_t contact = 0;
  for (const auto& r : read.value()) contact += r.contact;
  ASSERT_GT(contact, 50u) << "the hand should stroke the box";

  const ReplayComparison r = replay(read.value());
  EXPECT_EQ(r.rows, read.value().size());
  EXPECT_EQ(r.differing_rows, 0u);
  EXPECT_EQ(r.max_force_difference_N, 0.0);
  EXPECT_EQ(r.max_proxy_difference_m, 0.0);
  EXPECT_EQ(r.max_device_force_difference_N, 0.0);
}

TEST_F(RecordingReplay, AChangedInputIsFoundAtItsRow) {
  Result<std::vector<RecordingRow>> read = read_recording(*recording_);
  ASSERT_TRUE(read.ok());
  // Move the tool 0.1 mm in the middle of a contact stretch.
  std::size_t k = 0;
  for (std::size_t i = read.value().size() / 3; i < read.value().size(); ++i) {
    if (read.value()[i].contact != 0) {
      k = i;
      break;
    }
  }
  ASSERT_GT(k, 0u);
  read.value()[k].p_D_tool_m[1] += 1e-4;
  const ReplayComparison r = replay(read.value());
  EXPECT_GT(r.differing_rows, 0u);
  EXPECT_EQ(r.first_differing_row, k);
  EXPECT_GT(r.max_force_difference_N, 0.0);
}

TEST(RecordingReader, RefusesAMissingColumnAndABadNumberAtTheirLines) {
  const fs::path missing = temp_file("missing.csv");
  std::ofstream(missing) << "t_s,dt_s\n0,0.001\n";
  const auto a = read_recording(missing);
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.diagnostics().front().to_string(), missing.string() + ":1: error: missing column 'tool_D_x_m'");

  // A good recording with one number spoiled on its third data line (file line 4).
  const Result<std::vector<RecordingRow>> good = read_recording(std::string(MHD_SOURCE_DIR) + "/tests/data/server/recording_head.csv");
  ASSERT_TRUE(good.ok());
  ASSERT_GE(good.value().size(), 3u);
  std::ifstream in(std::string(MHD_SOURCE_DIR) + "/tests/data/server/recording_head.csv");
  std::string text, line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (n == 4) line.replace(line.find(','), 1, ",x");
    text += line + "\n";
  }
  const fs::path bad = temp_file("bad.csv");
  std::ofstream(bad) << text;
  const auto b = read_recording(bad);
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.diagnostics().front().to_string().rfind(bad.string() + ":4: error: column 'dt_s' is not a number: 'x", 0), 0u)
      << b.diagnostics().front().to_string();
}

TEST(RecordingReader, RefusesAHeaderNamingAColumnTwice) {
  // A good recording whose header names t_s twice, in place of the first column's name
  // being dropped: each data row then has the header's count of fields, and a column
  // looked up by name must never index past them.
  std::ifstream in(std::string(MHD_SOURCE_DIR) + "/tests/data/server/recording_head.csv");
  std::string header, rest, line;
  std::getline(in, header);
  while (std::getline(in, line)) rest += line + "\n";
  const fs::path twice = temp_file("twice.csv");
  std::ofstream(twice) << "t_s," << header << "\n" << rest;
  const auto r = read_recording(twice);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics().front().to_string(), twice.string() + ":1: error: column 't_s' named twice (fields 1 and 2)");
  // The dual: the header as written reads.
  const fs::path once = temp_file("once.csv");
  std::ofstream(once) << header << "\n" << rest;
  EXPECT_TRUE(read_recording(once).ok());
}

TEST(RecordingReader, ALineCutShortByACrashIsLeftOutAndTheRestIsRead) {
  std::ifstream in(std::string(MHD_SOURCE_DIR) + "/tests/data/server/recording_head.csv");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const fs::path cut = temp_file("cut.csv");
  std::ofstream(cut) << text << "0.5,0.001,0.1,0.2";  // a partial last line, no newline
  const auto r = read_recording(cut);
  ASSERT_TRUE(r.ok());
  const auto full = read_recording(std::string(MHD_SOURCE_DIR) + "/tests/data/server/recording_head.csv");
  EXPECT_EQ(r.value().size(), full.value().size());
}

TEST(RecordingReader, ARecordingFromBeforeTheLiftReadsWithTheArmAtZeroAndTheLiftRoundTrips) {
  // The same recording without its last column, lift_m, as recordings made before the
  // lift are: it reads, every row's lift at 0, every other number the same.
  const std::string source = std::string(MHD_SOURCE_DIR) + "/tests/data/server/recording_head.csv";
  std::ifstream in(source);
  std::string text, line;
  while (std::getline(in, line)) text += line.substr(0, line.rfind(',')) + "\n";
  ASSERT_EQ(text.substr(0, text.find('\n')).find("lift_m"), std::string::npos);
  const fs::path old = temp_file("before_lift.csv");
  std::ofstream(old) << text;
  const auto before = read_recording(old);
  const auto now = read_recording(source);
  ASSERT_TRUE(before.ok()) << before.error_text();
  ASSERT_TRUE(now.ok());
  ASSERT_EQ(before.value().size(), now.value().size());
  for (std::size_t i = 0; i < now.value().size(); ++i) {
    EXPECT_EQ(before.value()[i].lift_m, 0.0);
    EXPECT_EQ(before.value()[i].p_W_hip, now.value()[i].p_W_hip);
  }
  // A lift height, and a not-yet-known one, read back as written.
  const fs::path lifted = temp_file("lifted.csv");
  {
    CsvRecording out(lifted, 0.0);
    RecordingRow row = now.value().front();
    row.lift_m = 0.37251;
    out.write(row);
    row.lift_m = std::numeric_limits<double>::quiet_NaN();
    out.write(row);
  }
  const auto back = read_recording(lifted);
  ASSERT_TRUE(back.ok()) << back.error_text();
  ASSERT_EQ(back.value().size(), 2u);
  EXPECT_EQ(back.value()[0].lift_m, 0.37251);
  EXPECT_TRUE(std::isnan(back.value()[1].lift_m));
}

TEST(RecordingReader, TheSharedObjectsColumnsRoundTripAndOlderRecordingsReadWithout) {
  // recording_head.csv predates shared objects: no shared_* columns, every row NaN.
  const auto old = read_recording(std::string(MHD_SOURCE_DIR) + "/tests/data/server/recording_head.csv");
  ASSERT_TRUE(old.ok()) << old.error_text();
  for (const RecordingRow& r : old.value()) EXPECT_TRUE(std::isnan(r.p_W_shared_m[0]));
  const fs::path shared = temp_file("shared.csv");
  {
    CsvRecording out(shared, 0.0, /*shared_columns=*/true);
    RecordingRow row = old.value().front();
    row.p_W_shared_m = {0.125, 0.8, -0.0321};
    out.write(row);
    row.p_W_shared_m = {RecordingRow::kNoShared, RecordingRow::kNoShared, RecordingRow::kNoShared};
    out.write(row);
  }
  const auto back = read_recording(shared);
  ASSERT_TRUE(back.ok()) << back.error_text();
  ASSERT_EQ(back.value().size(), 2u);
  EXPECT_EQ(back.value()[0].p_W_shared_m, (std::array<double, 3>{0.125, 0.8, -0.0321}));
  EXPECT_TRUE(std::isnan(back.value()[1].p_W_shared_m[2]));
  EXPECT_EQ(back.value()[0].p_W_hip, old.value().front().p_W_hip);
  // Without the shared columns (a rig that shares nothing) the file is as before.
  const fs::path plain = temp_file("plain.csv");
  { CsvRecording out(plain, 0.0); out.write(old.value().front()); }
  std::ifstream in(plain);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, recording_csv_header());
}

}  // namespace
