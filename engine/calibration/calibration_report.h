#pragma once
// Text that `mhd calibrate` prints and writes: the before/after summary, the per-sample
// residuals CSV (for tools/plots/calibration_residuals.py), and the note that goes into the
// calibrated rig file.

#include "calibration/calibration_sample.h"
#include "calibration/rig_calibration.h"
#include "kinematics/rig.h"

#include <string>
#include <vector>

namespace mhd {

/// The summary: residual RMSE per axis before/after (mm), psi and the offsets with their
/// standard deviations, and which split rule placed SR and RP.
[[nodiscard]] std::string format_calibration_report(const CalibrationFit& result, OffsetSplit split);

/// Header of the residuals CSV (residual = measured - predicted HIP, world frame):
/// line,base_x_m,base_z_m,base_heading_rad,before_x_m,before_y_m,before_z_m,after_x_m,after_y_m,after_z_m
/// (line: the sample's line in its CSV; base: the planar base pose its tracker reading means).
inline constexpr std::string_view kResidualsHeader =
    "line,base_x_m,base_z_m,base_heading_rad,before_x_m,before_y_m,before_z_m,after_x_m,after_y_m,after_z_m";

[[nodiscard]] std::string format_residuals_csv(const Rig& rig, const std::vector<CalibrationSample>& samples,
                                               const CalibrationFit& result);

/// Lines for the comment in the calibrated rig file.
[[nodiscard]] std::vector<std::string> calibration_note_lines(const CalibrationFit& result,
                                                              const std::string& samples_file, OffsetSplit split);

}  // namespace mhd
