// The HIP path CSV reader (engine/recording/hip_path_csv.h): good files, and each kind of
// bad input with its exact message at file:line.

#include "recording/hip_path_csv.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace {

using mhd::HipPathCsvReader;
using mhd::HipPathSample;

struct ReadAll {
  std::vector<HipPathSample> samples;
  std::string error;  ///< Diagnostic::to_string(), empty without one
};

ReadAll read_all(const std::string& text) {
  std::istringstream in(text);
  HipPathCsvReader reader(in, "hip.csv");
  ReadAll r;
  while (const auto s = reader.next()) r.samples.push_back(*s);
  if (reader.error()) r.error = reader.error()->to_string();
  return r;
}

std::string error_of(const std::string& text) { return read_all(text).error; }

TEST(HipPathCsv, ReadsEveryRowWithItsLine) {
  const ReadAll r = read_all("t_s,x_m,y_m,z_m\n0,1,2,3\n0.001,-1e-3,+2.5,0.1\n");
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.samples.size(), 2u);
  EXPECT_EQ(r.samples[0].t_s, 0.0);
  EXPECT_EQ(r.samples[0].p_W_hip_m, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(r.samples[0].line, 2);
  EXPECT_EQ(r.samples[1].t_s, 0.001);
  EXPECT_EQ(r.samples[1].p_W_hip_m, Eigen::Vector3d(-1e-3, 2.5, 0.1));
  EXPECT_EQ(r.samples[1].line, 3);
}

TEST(HipPathCsv, NumbersRoundTripExactly) {
  const ReadAll r = read_all("t_s,x_m,y_m,z_m\n0.1,0.30000000000000004,1e-300,-0.2\n");
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.samples.size(), 1u);
  EXPECT_EQ(r.samples[0].p_W_hip_m.x(), 0.1 + 0.2);
  EXPECT_EQ(r.samples[0].p_W_hip_m.y(), 1e-300);
}

TEST(HipPathCsv, AcceptsCrlfAndALastLineWithoutNewline) {
  const ReadAll r = read_all("t_s,x_m,y_m,z_m\r\n0,1,2,3\r\n1,4,5,6");
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.samples.size(), 2u);
  EXPECT_EQ(r.samples[1].p_W_hip_m, Eigen::Vector3d(4, 5, 6));
}

TEST(HipPathCsv, MissingFile) {
  HipPathCsvReader reader(std::filesystem::path("no/such/hip.csv"));
  ASSERT_TRUE(reader.error());
  EXPECT_EQ(reader.error()->to_string(), "no/such/hip.csv: error: HIP path file not found");
  EXPECT_FALSE(reader.next());
}

TEST(HipPathCsv, EmptyFile) {
  EXPECT_EQ(error_of(""), "hip.csv:1: error: the file is empty (the header must be t_s,x_m,y_m,z_m)");
}

TEST(HipPathCsv, HeaderWithoutRows) {
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n"),
            "hip.csv:2: error: no rows after the header (one row of t_s,x_m,y_m,z_m per tick)");
}

TEST(HipPathCsv, HeaderMissingAColumn) {
  EXPECT_EQ(error_of("t_s,x_m,y_m\n0,1,2\n"),
            "hip.csv:1: error: missing column 'z_m' (the header must be t_s,x_m,y_m,z_m)");
}

TEST(HipPathCsv, HeaderWithAMisnamedColumn) {
  EXPECT_EQ(error_of("t_s,x,y_m,z_m\n0,1,2,3\n"),
            "hip.csv:1: error: column 2 is 'x', expected 'x_m' (the header must be t_s,x_m,y_m,z_m)");
}

TEST(HipPathCsv, HeaderWithAnExtraColumn) {
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m,w\n0,1,2,3,4\n"),
            "hip.csv:1: error: extra column 5 'w' (the header must be t_s,x_m,y_m,z_m)");
}

TEST(HipPathCsv, RowMissingAField) {
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,1,2,3\n0.001,1,2\n"),
            "hip.csv:3: error: missing column 'z_m' (found 3 fields, expected 4: t_s,x_m,y_m,z_m)");
}

TEST(HipPathCsv, RowWithAnExtraField) {
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,1,2,3,9\n"),
            "hip.csv:2: error: extra field 5 '9' (found 5 fields, expected 4: t_s,x_m,y_m,z_m)");
}

TEST(HipPathCsv, EmptyLine) {
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,1,2,3\n\n1,1,2,3\n"),
            "hip.csv:3: error: empty line (each row must be t_s,x_m,y_m,z_m)");
}

TEST(HipPathCsv, NotANumber) {
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,1,2,3\n0.001,1,2mm,3\n"),
            "hip.csv:3: error: column 'y_m': '2mm' is not a number");
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,,2,3\n"), "hip.csv:2: error: column 'x_m': '' is not a number");
}

TEST(HipPathCsv, NanAndInfinity) {
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,1,2,nan\n"), "hip.csv:2: error: column 'z_m' is not finite (nan)");
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,1,2,3\n0.001,-inf,2,3\n"),
            "hip.csv:3: error: column 'x_m' is not finite (-inf)");
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n1e999,1,2,3\n"), "hip.csv:2: error: column 't_s': '1e999' is out of range");
}

TEST(HipPathCsv, TimeMustIncrease) {
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,1,2,3\n0.001,1,2,3\n0.001,1,2,3\n"),
            "hip.csv:4: error: column 't_s': 0.001 is not after the previous row's 0.001 (time must increase)");
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0.5,1,2,3\n0.25,1,2,3\n"),
            "hip.csv:3: error: column 't_s': 0.25 is not after the previous row's 0.5 (time must increase)");
}

TEST(HipPathCsv, AbsurdlyLongLineStopsAtTheLimit) {
  const std::string row = "0," + std::string(mhd::kHipPathMaxLineBytes, '1') + ",2,3\n";
  EXPECT_EQ(error_of("t_s,x_m,y_m,z_m\n0,1,2,3\n" + row), "hip.csv:3: error: line longer than 1024 bytes");
  EXPECT_EQ(error_of(std::string(5000, 'a')),
            "hip.csv:1: error: the header line is longer than 1024 bytes (the header must be t_s,x_m,y_m,z_m)");
}

TEST(HipPathCsv, ALineOfExactlyTheLimitIsRead) {
  std::string row = "0,1,2,";
  row += std::string(mhd::kHipPathMaxLineBytes - row.size() - 1, '0') + "3";
  ASSERT_EQ(row.size(), mhd::kHipPathMaxLineBytes);
  const ReadAll r = read_all("t_s,x_m,y_m,z_m\n" + row + "\n");
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.samples.size(), 1u);
  EXPECT_EQ(r.samples[0].p_W_hip_m.z(), 3.0);
}

TEST(HipPathCsv, StopsAtTheFirstProblem) {
  std::istringstream in("t_s,x_m,y_m,z_m\n0,1,2,3\n0.001,x,2,3\n0.002,1,2,3\n");
  HipPathCsvReader reader(in, "hip.csv");
  EXPECT_TRUE(reader.next());
  EXPECT_FALSE(reader.next());
  EXPECT_FALSE(reader.next());
  ASSERT_TRUE(reader.error());
  EXPECT_EQ(reader.error()->where.line, 3);
}

}  // namespace
