#include "replay_csv.h"
#include "replay_model.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace mhd::tracker_replay {
namespace {

const std::string kData = "tests/data/replay/";  // tests run from the source root

std::string error_of(const std::string& file) {
  try {
    (void)read_replay_csv(kData + file);
  } catch (const ReplayError& e) {
    return e.what();
  }
  return "";
}

TEST(ReplayCsv, ReadsAValidFile) {
  // CRLF line ends and a blank line.
  const auto samples = read_replay_csv(kData + "valid.csv");
  ASSERT_EQ(samples.size(), 5u);
  EXPECT_EQ(samples[0].timestamp_s, 100.0);
  EXPECT_EQ(samples[0].sensor_id, 0u);
  EXPECT_EQ(samples[0].sequence, 7u);
  EXPECT_EQ(samples[1].sensor_id, 1u);
  EXPECT_EQ(samples[1].p_T_m[1], 1.65);
  EXPECT_NEAR(samples[1].q_T_wxyz[2], 0.7071067811865476, 1e-15);
  EXPECT_EQ(samples[4].timestamp_s, 100.025);
  EXPECT_EQ(samples[4].p_T_m[0], 1.02);
}

TEST(ReplayCsv, NamesTheFileAndLineOfABadRow) {
  EXPECT_EQ(error_of("missing_column.csv"),
            kData + "missing_column.csv:3: expected 10 columns (timestamp_s,sensor_id,sequence,px,py,pz,qw,qx,qy,qz), got 9");
  EXPECT_EQ(error_of("nan.csv"), kData + "nan.csv:3: column 'py' is not finite: 'nan'");
  EXPECT_EQ(error_of("not_a_number.csv"), kData + "not_a_number.csv:3: column 'pz' is not a number: '3x'");
  EXPECT_EQ(error_of("sequence_not_increasing.csv"),
            kData + "sequence_not_increasing.csv:5: sequence 2 of sensor 0 does not increase (line 3 has 2)");
  EXPECT_EQ(error_of("time_goes_back.csv"),
            kData + "time_goes_back.csv:3: timestamp_s 0.1 is earlier than line 2's 0.2");
  EXPECT_EQ(error_of("bad_quaternion.csv"),
            kData + "bad_quaternion.csv:2: quaternion qw,qx,qy,qz has norm 0.500000, expected 1");
  EXPECT_EQ(error_of("negative_sensor.csv"),
            kData + "negative_sensor.csv:2: column 'sensor_id' must be an integer from 0 to 4294967295, got '-1'");
}

TEST(ReplayCsv, NamesTheFileOfABadHeaderOrNoData) {
  EXPECT_EQ(error_of("bad_header.csv"),
            kData + "bad_header.csv:1: expected the header 'timestamp_s,sensor_id,sequence,px,py,pz,qw,qx,qy,qz', "
                    "got 'time,sensor,seq,x,y,z,qw,qx,qy,qz'");
  EXPECT_EQ(error_of("empty.csv"),
            kData + "empty.csv: empty file, expected the header 'timestamp_s,sensor_id,sequence,px,py,pz,qw,qx,qy,qz'");
  EXPECT_EQ(error_of("header_only.csv"), kData + "header_only.csv: no samples after the header");
  EXPECT_EQ(error_of("no_such_file.csv"), kData + "no_such_file.csv: cannot open the replay file");
}

TEST(ReplayModel, PlaysAtTheRecordedTimesFromStart) {
  ReplayModel m(read_replay_csv(kData + "valid.csv"));
  m.start(7.0);  // the first sample (recorded at 100.000) is due at 7.0
  std::vector<mhd_tracker_sample> out(8);
  EXPECT_EQ(m.read(6.999, out), 0u);
  ASSERT_EQ(m.read(7.0, out), 2u);
  EXPECT_EQ(out[0].timestamp_s, 7.0);
  EXPECT_EQ(out[1].sensor_id, 1u);
  EXPECT_EQ(m.read(7.009, out), 0u);
  ASSERT_EQ(m.read(7.02, out), 2u);
  EXPECT_NEAR(out[0].timestamp_s, 7.01, 1e-12);
  EXPECT_EQ(out[0].sequence, 8u);
  EXPECT_FALSE(m.finished());
  ASSERT_EQ(m.read(100.0, out), 1u);
  EXPECT_TRUE(m.finished());
  EXPECT_EQ(m.read(200.0, out), 0u);
  m.start(300.0);  // plays again from the beginning
  EXPECT_EQ(m.read(300.0, out), 2u);
}

TEST(ReplayModel, HandsOutNoMoreThanAsked) {
  ReplayModel m(read_replay_csv(kData + "valid.csv"));
  m.start(0.0);
  std::vector<mhd_tracker_sample> out(1);
  EXPECT_EQ(m.read(1.0, out), 1u);
  EXPECT_EQ(out[0].sequence, 7u);
  EXPECT_EQ(m.read(1.0, out), 1u);
  EXPECT_EQ(out[0].sequence, 3u);
}

TEST(ReplayCsv, ParsesAStream) {
  std::istringstream in("timestamp_s, sensor_id ,sequence,px,py,pz,qw,qx,qy,qz\n1,2,3,4,5,6,0,0,0,1\n");
  const auto samples = parse_replay_csv(in, "memory");
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_EQ(samples[0].sensor_id, 2u);
  EXPECT_EQ(samples[0].q_T_wxyz[3], 1.0);
}

}  // namespace
}  // namespace mhd::tracker_replay
