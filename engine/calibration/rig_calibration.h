#pragma once
// Kinematic calibration of the rig (thesis ch. 4.4, eq. 4.6, plus the yaw psi it proposes).
//
// The unknowns are the two measured offsets of the chain and one yaw:
//   SR   = p_S_robot:   the robot origin in the base_sensor frame (thesis SRx, SRy, SRz;
//                       the rig's base_sensor y is the thesis's -y, docs/kinematics.md)
//   RP   = p_R_phantom: the PHANToM origin in the robot frame (RPx, RPy, RPz)
//   psi  = the robot frame's yaw about base_sensor's z (vertical), on top of the rig's
//          robot rotation: R_S_robot = Rz(psi) R_S_robot(rig)
// so that p_W_hip = X_W_is900 X_is900_S (SR + Rz(psi) R_SR (RP + R_RP p_P_tool(q))).
//
// What the samples can tell apart: only c = SR + Rz(psi) R_SR RP (the PHANToM origin in
// base_sensor) and psi. Both offsets are rigid steps between the same two measured frames,
// so moving SR by d and RP by -(Rz(psi) R_SR)^T d changes no prediction: eq. 4.6's columns
// are pairwise equal or opposite (SRx = -RPy, SRy = -RPx, SRz = RPz) for every phi. The fit
// therefore estimates (c, psi) by Levenberg-Marquardt and then splits c's change between SR
// and RP by a stated rule (OffsetSplit); the even split is the least-squares solution
// closest to the starting values, which is what the thesis's fit from its ruler values
// returned (its SRz and RPz both moved by -17.6 mm).

#include "calibration/calibration_sample.h"
#include "geometry/pose.h"
#include "kinematics/rig.h"

#include <Eigen/Core>

#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mhd {

struct RigOffsets {
  Eigen::Vector3d p_S_robot_m = Eigen::Vector3d::Zero();    ///< SR, in base_sensor
  Eigen::Vector3d p_R_phantom_m = Eigen::Vector3d::Zero();  ///< RP, in robot
  double psi_rad = 0.0;  ///< extra yaw of robot about base_sensor's z, relative to the rig's rotation
};

/// The rig's own offsets (psi = 0).
[[nodiscard]] RigOffsets offsets_of(const Rig& rig) noexcept;

/// The thesis's calibrated values in the rig's frames: SR (203.1, -1.8, -387.6) mm,
/// RP (-2.1, -232.8, 41.6) mm; psi = 1.5 degrees (the thesis did not estimate psi; MHD's pick).
[[nodiscard]] RigOffsets thesis_calibrated_offsets() noexcept;

/// base_sensor -> robot and robot -> phantom with `offsets` in place of the rig's.
[[nodiscard]] Pose calibrated_X_base_sensor_robot(const Rig& rig, const RigOffsets& offsets) noexcept;
[[nodiscard]] Pose calibrated_X_robot_phantom(const Rig& rig, const RigOffsets& offsets) noexcept;

/// The HIP in the world for a tracker reading, joint angles and the lift's height, with
/// `offsets`.
[[nodiscard]] Eigen::Vector3d predicted_p_W_hip(const Rig& rig, const RigOffsets& offsets,
                                                const Pose& X_is900_base_sensor, const Eigen::Vector3d& q_rad,
                                                double lift_m = 0.0) noexcept;

/// Per-axis and overall residual statistics (residual = measured - predicted).
struct ResidualStats {
  std::vector<Eigen::Vector3d> residuals_m;  ///< one per sample
  Eigen::Vector3d rmse_m = Eigen::Vector3d::Zero();  ///< per world axis
  double rmse_3d_m = 0.0;                            ///< sqrt(mean |r|^2)
  Eigen::Vector3d max_abs_m = Eigen::Vector3d::Zero();
};
[[nodiscard]] ResidualStats residual_stats(const Rig& rig, const RigOffsets& offsets,
                                           const std::vector<CalibrationSample>& samples);

/// How the estimated c is split between SR and RP (the data cannot tell).
enum class OffsetSplit {
  Even,               ///< the least change of (SR, RP) from the rig's values (pseudo-inverse)
  HoldSensorToRobot,  ///< keep SR, move RP
  HoldRobotToPhantom  ///< keep RP, move SR
};
[[nodiscard]] std::optional<OffsetSplit> offset_split_from_string(std::string_view name) noexcept;
[[nodiscard]] std::string_view to_string(OffsetSplit split) noexcept;

struct CalibrationOptions {
  OffsetSplit split = OffsetSplit::Even;
  int min_samples = 10;
  bool estimate_psi = true;  ///< false: psi stays 0 (the thesis's six-offset fit)
  /// Above this condition number of the column-scaled Jacobian a parameter is unobservable.
  double max_condition = 1e4;
  /// Above these standard deviations (from the residuals) the fit is refused as poorly determined.
  double max_psi_sigma_rad = 0.5 * std::numbers::pi / 180.0;
  double max_offset_sigma_m = 0.005;
  int max_iterations = 100;
};

enum class CalibrationErrorKind {
  TooFewSamples,     ///< fewer than min_samples
  Unobservable,      ///< the samples do not constrain a parameter (parameter names it)
  PoorlyDetermined,  ///< constrained, but with a standard deviation over the limit
  NotConverged,      ///< Levenberg-Marquardt ran out of iterations
};

struct CalibrationError {
  CalibrationErrorKind kind = CalibrationErrorKind::TooFewSamples;
  std::string parameter;  ///< e.g. "psi"; empty when not about one parameter
  std::string message;
};

/// Indices into CalibrationFit::sigma and the Jacobian's columns.
enum CalibrationParameter : int { kPhantomInSensorX = 0, kPhantomInSensorY, kPhantomInSensorZ, kPsi };

struct CalibrationFit {
  RigOffsets before;  ///< the rig's offsets
  RigOffsets after;   ///< calibrated (SR, RP split per options.split)
  Eigen::Vector3d p_S_phantom_before_m = Eigen::Vector3d::Zero();  ///< c with the rig's values
  Eigen::Vector3d p_S_phantom_m = Eigen::Vector3d::Zero();         ///< c, estimated
  Eigen::Vector4d sigma = Eigen::Vector4d::Zero();  ///< standard deviations of (c x, y, z [m], psi [rad])
  double condition_number = 0.0;  ///< of the column-scaled Jacobian at the solution
  int iterations = 0;
  ResidualStats residuals_before;
  ResidualStats residuals_after;
};

/// Each sample whose lift height the rig cannot have, at its line of `file`: off 0 on a rig
/// without a lift, or outside the lift's range (1 mm of reading error allowed).
[[nodiscard]] Diagnostics lift_problems(const Rig& rig, const std::vector<CalibrationSample>& samples,
                                        const std::string& file);

/// Least-squares fit of (c, psi) to the samples, starting from the rig's values.
[[nodiscard]] Result<CalibrationFit, CalibrationError> calibrate_rig(const Rig& rig,
                                                                     const std::vector<CalibrationSample>& samples,
                                               const CalibrationOptions& options = {});

/// SR and RP from the estimated c and psi, starting from `start`, per `split`.
[[nodiscard]] RigOffsets split_offsets(const Rig& rig, const RigOffsets& start, const Eigen::Vector3d& p_S_phantom_m,
                                       double psi_rad, OffsetSplit split) noexcept;

}  // namespace mhd
