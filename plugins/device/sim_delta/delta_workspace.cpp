#include "delta_workspace.h"

#include <Eigen/SVD>

#include <algorithm>
#include <limits>

namespace mhd::sim_delta {

bool DeltaWorkspaceBox::contains(const Eigen::Vector3d& p_D_m) const noexcept {
  return (p_D_m.array() >= min_D_m.array()).all() && (p_D_m.array() <= max_D_m.array()).all();
}

Eigen::Vector3d DeltaWorkspaceBox::clamp(const Eigen::Vector3d& p_D_m, bool& clamped) const noexcept {
  const Eigen::Vector3d c = p_D_m.cwiseMax(min_D_m).cwiseMin(max_D_m);
  if (c != p_D_m) clamped = true;
  return c;
}

double condition_number(const Eigen::Matrix3d& J) noexcept {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(J);
  const Eigen::Vector3d s = svd.singularValues();
  if (!(s[2] > 0.0)) return std::numeric_limits<double>::infinity();
  return s[0] / s[2];
}

WorkspaceSurvey survey_workspace(const DeltaGeometry& geometry, const DeltaJointLimits& limits,
                                 const DeltaWorkspaceBox& box, int samples_per_axis, double max_condition) noexcept {
  WorkspaceSurvey survey;
  if (samples_per_axis < 2) return survey;
  const Eigen::Vector3d step = box.size_m() / static_cast<double>(samples_per_axis - 1);
  for (int i = 0; i < samples_per_axis; ++i) {
    for (int j = 0; j < samples_per_axis; ++j) {
      for (int k = 0; k < samples_per_axis; ++k) {
        ++survey.points;
        const Eigen::Vector3d p = box.min_D_m + step.cwiseProduct(Eigen::Vector3d(i, j, k));
        const std::optional<Eigen::Vector3d> q = delta_inverse_kinematics(geometry, limits, p);
        const std::optional<Eigen::Matrix3d> J = q ? delta_jacobian(geometry, *q) : std::nullopt;
        const double condition = J ? condition_number(*J) : std::numeric_limits<double>::infinity();
        if (!(condition <= max_condition)) {
          ++survey.unreached;
          continue;
        }
        survey.worst_condition = std::max(survey.worst_condition, condition);
        survey.max_jacobian_column_m = std::max(survey.max_jacobian_column_m, J->colwise().norm().maxCoeff());
      }
    }
  }
  return survey;
}

}  // namespace mhd::sim_delta
