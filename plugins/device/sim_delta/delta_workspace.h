#pragma once
// The delta's workspace: an axis-aligned box in the device frame D that the effector
// reaches everywhere, and the survey (a grid over the box) that checks it and sizes the
// motors. A grid cannot prove a box reachable between its points; the default box keeps
// a margin (docs/sim_delta.md) and the tests survey it on a finer grid.

#include "delta_kinematics.h"

#include <Eigen/Core>

#include <cstddef>

namespace mhd::sim_delta {

/// Default: 70 x 70 x 60 mm (x, y, z), x and y within +-35 mm of the axis, z from 60 to
/// 120 mm off the base. Found by growing boxes on the axis over a grid of 9^3 points,
/// requiring every point to be reached within DeltaJointLimits{} with a Jacobian
/// condition number below 10; the largest such box there is about 80 x 80 x 60 mm, this
/// one keeps 5 mm of margin in x and y. Smaller than the Falcon's advertised 4-inch cube
/// (101.6 mm): the ideal delta omits the Falcon's tilted legs and offsets.
struct DeltaWorkspaceBox {
  Eigen::Vector3d min_D_m{-0.035, -0.035, 0.060};
  Eigen::Vector3d max_D_m{0.035, 0.035, 0.120};

  [[nodiscard]] bool contains(const Eigen::Vector3d& p_D_m) const noexcept;
  [[nodiscard]] Eigen::Vector3d center_D_m() const noexcept { return 0.5 * (min_D_m + max_D_m); }
  [[nodiscard]] Eigen::Vector3d size_m() const noexcept { return max_D_m - min_D_m; }
  /// The nearest point of the box; `clamped` is set when it differs from p_D_m.
  [[nodiscard]] Eigen::Vector3d clamp(const Eigen::Vector3d& p_D_m, bool& clamped) const noexcept;
};

struct WorkspaceSurvey {
  std::size_t points = 0;
  /// Grid points with no inverse kinematics within the limits, no Jacobian, or a
  /// Jacobian condition number above the bound.
  std::size_t unreached = 0;
  /// Over the reached points: the largest condition number of J_D, and the largest
  /// |column j of J_D| (metres per radian), which sizes the motors: tau_j = J_D.col(j) . F.
  double worst_condition = 0.0;
  double max_jacobian_column_m = 0.0;
  [[nodiscard]] bool all_reached() const noexcept { return unreached == 0 && points > 0; }
};

/// Surveys the box on a grid of samples_per_axis^3 points (faces and corners included;
/// samples_per_axis >= 2, fewer gives an empty survey).
[[nodiscard]] WorkspaceSurvey survey_workspace(const DeltaGeometry& geometry, const DeltaJointLimits& limits,
                                               const DeltaWorkspaceBox& box, int samples_per_axis,
                                               double max_condition) noexcept;

/// The 2-norm condition number of J (infinity when singular).
[[nodiscard]] double condition_number(const Eigen::Matrix3d& J) noexcept;

}  // namespace mhd::sim_delta
