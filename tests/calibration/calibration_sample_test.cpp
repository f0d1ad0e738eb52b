// The samples CSV (engine/calibration/calibration_sample.h): round trip and every bad-input
// message, compared exactly.

#include "calibration/calibration_sample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

namespace mhd {
namespace {

constexpr const char* kHeader =
    "sensor_x_m,sensor_y_m,sensor_z_m,sensor_qw,sensor_qx,sensor_qy,sensor_qz,theta1_rad,theta2_rad,theta3_rad,"
    "hip_x_m,hip_y_m,hip_z_m\n";
constexpr const char* kRow = "0.2,0.1,1.4,1,0,0,0,0.1,0.2,0.3,0.5,1.0,-0.2\n";

std::string messages(const Result<std::vector<CalibrationSample>>& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics()) out += d.to_string() + "\n";
  return out;
}

TEST(CalibrationSamples, RoundTripKeepsEveryValue) {
  std::vector<CalibrationSample> samples(3);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double k = static_cast<double>(i);
    samples[i].X_is900_base_sensor =
        pose_from_xyz_rpy(Eigen::Vector3d(0.2 + k, -0.1, 1.44), Eigen::Vector3d(std::numbers::pi, 0.0, 0.3 * k));
    samples[i].q_rad = Eigen::Vector3d(0.1 * k, 0.2, -0.3);
    samples[i].p_W_hip_measured_m = Eigen::Vector3d(k, 1.0, -0.5);
  }
  const std::string text = format_calibration_samples(samples, {"a comment", "another"});
  EXPECT_EQ(text.rfind("# a comment\n# another\nsensor_x_m,", 0), 0U) << text;
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples(text, "round.csv");
  ASSERT_TRUE(read.ok()) << messages(read);
  ASSERT_EQ(read.value().size(), samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_TRUE(read.value()[i].X_is900_base_sensor.isApprox(samples[i].X_is900_base_sensor, 1e-9));
    EXPECT_TRUE(read.value()[i].q_rad.isApprox(samples[i].q_rad, 1e-9));
    EXPECT_TRUE(read.value()[i].p_W_hip_measured_m.isApprox(samples[i].p_W_hip_measured_m, 1e-9));
    EXPECT_EQ(read.value()[i].line, static_cast<int>(i) + 4);  // two comments and the header first
  }
}

TEST(CalibrationSamples, ColumnsAreFoundByNameInAnyOrderAndExtraColumnsAreIgnored) {
  const std::string text =
      "t_s,hip_z_m,hip_y_m,hip_x_m,theta3_rad,theta2_rad,theta1_rad,sensor_qz,sensor_qy,sensor_qx,sensor_qw,"
      "sensor_z_m,sensor_y_m,sensor_x_m\n"
      "\n# a note\n"
      "7.5,-0.2,1.0,0.5,0.3,0.2,0.1,0,0,0,1,1.4,0.1,0.2\n";
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples(text, "any_order.csv");
  ASSERT_TRUE(read.ok()) << messages(read);
  ASSERT_EQ(read.value().size(), 1U);
  EXPECT_TRUE(read.value()[0].X_is900_base_sensor.translation().isApprox(Eigen::Vector3d(0.2, 0.1, 1.4)));
  EXPECT_TRUE(read.value()[0].q_rad.isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  EXPECT_TRUE(read.value()[0].p_W_hip_measured_m.isApprox(Eigen::Vector3d(0.5, 1.0, -0.2)));
  EXPECT_EQ(read.value()[0].line, 4);
}

TEST(CalibrationSamples, MissingColumnNamesTheHeaderLine) {
  const std::string text = "# comment\nsensor_x_m,sensor_y_m,sensor_z_m,sensor_qw,sensor_qx,sensor_qy,sensor_qz,"
                           "theta1_rad,theta3_rad,hip_x_m,hip_y_m,hip_z_m\n";
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples(text, "s.csv");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(messages(read),
            "s.csv:2: error: missing column 'theta2_rad' (a samples file needs the columns "
            "sensor_x_m,sensor_y_m,sensor_z_m,sensor_qw,sensor_qx,sensor_qy,sensor_qz,theta1_rad,theta2_rad,"
            "theta3_rad,hip_x_m,hip_y_m,hip_z_m)\n");
  EXPECT_FALSE(read.ok());
}

TEST(CalibrationSamples, DuplicateColumnIsAnError) {
  const std::string text = std::string("hip_x_m,") + kHeader;
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples(text, "s.csv");
  EXPECT_EQ(messages(read), "s.csv:1: error: column 'hip_x_m' appears twice\n");
}

TEST(CalibrationSamples, NanAndInfinityNameLineAndColumn) {
  const std::string text = std::string(kHeader) + kRow + "0.2,0.1,1.4,1,0,0,0,0.1,0.2,0.3,nan,1.0,-0.2\n" +
                           "0.2,0.1,1.4,1,0,0,0,inf,0.2,0.3,0.5,1.0,-0.2\n";
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples(text, "s.csv");
  EXPECT_EQ(messages(read),
            "s.csv:3: error: column 'hip_x_m' is not finite (nan)\n"
            "s.csv:4: error: column 'theta1_rad' is not finite (inf)\n");
  EXPECT_FALSE(read.ok()) << "no samples from a file with errors";
}

TEST(CalibrationSamples, NotANumberAndWrongFieldCount) {
  const std::string text = std::string(kHeader) + "0.2,0.1,1.4,1,0,0,0,0.1,0.2,0.3,0.5,1.0mm,-0.2\n" +
                           "0.2,0.1,1.4,1,0,0,0,0.1,0.2,0.3,0.5,1.0\n" + "0.2,0.1,1.4,1,0,0,0,0.1,,0.3,0.5,1.0,-0.2\n";
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples(text, "s.csv");
  EXPECT_EQ(messages(read),
            "s.csv:2: error: column 'hip_y_m': '1.0mm' is not a number\n"
            "s.csv:3: error: expected 13 fields (as in the header), found 12\n"
            "s.csv:4: error: column 'theta2_rad': '' is not a number\n");
}

TEST(CalibrationSamples, QuaternionMustBeUnit) {
  const std::string text = std::string(kHeader) + "0.2,0.1,1.4,0.5,0,0,0,0.1,0.2,0.3,0.5,1.0,-0.2\n" +
                           "0.2,0.1,1.4,1.0004,0,0,0,0.1,0.2,0.3,0.5,1.0,-0.2\n";
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples(text, "s.csv");
  EXPECT_EQ(messages(read),
            "s.csv:2: error: sensor quaternion (sensor_qw, sensor_qx, sensor_qy, sensor_qz) has norm 0.5; it must "
            "be a unit quaternion\n");
}

TEST(CalibrationSamples, EmptyFileHasNoHeader) {
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples("# only a comment\n\n", "e.csv");
  ASSERT_EQ(read.error().size(), 1U);
  EXPECT_EQ(read.error()[0].where.line, 0);
  EXPECT_EQ(read.error()[0].to_string().rfind("e.csv: error: no header line (expected the columns sensor_x_m,", 0), 0U)
      << read.error()[0].to_string();
}

TEST(CalibrationSamples, MissingFileIsReported) {
  const Result<std::vector<CalibrationSample>> read = read_calibration_samples("tests/data/calibration/no_such.csv");
  EXPECT_EQ(messages(read), "tests/data/calibration/no_such.csv: error: samples file not found\n");
}

TEST(CalibrationSamples, ReadsTheCheckedInFile) {
  const Result<std::vector<CalibrationSample>> read =
      read_calibration_samples(std::filesystem::path(MHD_SOURCE_DIR) / "tests/data/calibration/synthetic_100.csv");
  ASSERT_TRUE(read.ok()) << messages(read);
  EXPECT_EQ(read.value().size(), 100U);
}

}  // namespace
TEST(CalibrationSamples, TheLiftsHeightRoundTripsAndIsOptional) {
  std::vector<CalibrationSample> samples(2);
  samples[0].lift_m = 0.0;
  samples[1].lift_m = -0.4375;
  const std::string text = format_calibration_samples(samples, {});
  EXPECT_NE(text.find(",lift_m\n"), std::string::npos) << text;
  const Result<std::vector<CalibrationSample>> read = parse_calibration_samples(text, "lift.csv");
  ASSERT_TRUE(read.ok()) << messages(read);
  EXPECT_EQ(read.value()[0].lift_m, 0.0);
  EXPECT_EQ(read.value()[1].lift_m, -0.4375);
  // A rig without a lift writes no lift column, and a file without one reads as 0.
  samples[1].lift_m = 0.0;
  const std::string flat = format_calibration_samples(samples, {});
  EXPECT_EQ(flat.find("lift_m"), std::string::npos);
  const Result<std::vector<CalibrationSample>> none = parse_calibration_samples(flat, "flat.csv");
  ASSERT_TRUE(none.ok());
  EXPECT_EQ(none.value()[1].lift_m, 0.0);
  // A height that is not a finite number is refused at its line and column.
  std::string bad = text;
  bad.replace(bad.rfind("-0.4375"), 7, "nan");
  const Result<std::vector<CalibrationSample>> refused = parse_calibration_samples(bad, "lift.csv");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(messages(refused), "lift.csv:3: error: column 'lift_m' is not finite (nan)\n");
}

}  // namespace mhd
