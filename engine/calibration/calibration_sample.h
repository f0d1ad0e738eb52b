#pragma once
// Samples for the kinematic calibration (thesis ch. 4.4): what the tracker says about the
// base station, the device's joint angles, and the HIP measured in the world (a tracker
// marker held at the HIP). docs/calibration.md documents the CSV.
//
// CSV: a header line naming the columns, then one sample per line. Columns are found by
// name, in any order; other columns are ignored. Lines starting with '#' and blank lines
// are skipped (the synthesizer writes the truth there).
//   sensor_x_m, sensor_y_m, sensor_z_m                 X_is900_base_sensor position (the
//   sensor_qw, sensor_qx, sensor_qy, sensor_qz         tracker's p_T_m, q_T_wxyz), unit quaternion
//   theta1_rad, theta2_rad, theta3_rad                 the device's joint angles
//   hip_x_m, hip_y_m, hip_z_m                          the HIP measured in the world

#include "geometry/pose.h"
#include "diagnostics/result.h"

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mhd {

struct CalibrationSample {
  Pose X_is900_base_sensor = Pose::Identity();  ///< the base station's tracker reading
  Eigen::Vector3d q_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_W_hip_measured_m = Eigen::Vector3d::Zero();
  /// The lift's height when the sample was taken (column lift_m, optional: 0 without; a
  /// rig without a lift has it at 0 for ever).
  double lift_m = 0.0;
  int line = 0;  ///< the CSV line it came from; 0 when made in code
};

/// The optional column of the lift's height (docs/calibration.md, "With a lift").
inline constexpr std::string_view kCalibrationLiftColumn = "lift_m";

/// The columns a samples file must have (any order; more are allowed).
inline constexpr std::array<std::string_view, 13> kCalibrationSampleColumns = {
    "sensor_x_m", "sensor_y_m", "sensor_z_m", "sensor_qw", "sensor_qx",  "sensor_qy", "sensor_qz",
    "theta1_rad", "theta2_rad", "theta3_rad", "hip_x_m",   "hip_y_m",   "hip_z_m"};

/// A sensor quaternion's norm may be off 1 by this much (it is normalised); more is an error.
inline constexpr double kQuaternionNormTolerance = 1e-3;

/// Reads a samples CSV. Errors name the line: missing or duplicate columns, a wrong field
/// count, a field that is not a number, NaN or infinity, a quaternion that is not unit.
[[nodiscard]] Result<std::vector<CalibrationSample>> read_calibration_samples(const std::filesystem::path& file);

/// The same from memory; `file` names the source in messages.
[[nodiscard]] Result<std::vector<CalibrationSample>> parse_calibration_samples(std::string_view text, const std::string& file);

/// The CSV text for `samples`: each comment line (without '#') first, then the header.
[[nodiscard]] std::string format_calibration_samples(const std::vector<CalibrationSample>& samples,
                                                     const std::vector<std::string>& comments = {});

}  // namespace mhd
