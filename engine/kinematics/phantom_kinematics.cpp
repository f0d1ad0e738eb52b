#include "kinematics/phantom_kinematics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mhd {

namespace {

constexpr double deg(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

bool PhantomJointLimits::contains(const Eigen::Vector3d& q_rad) const noexcept {
  const double difference = q_rad.z() - q_rad.y();
  return (q_rad.array() >= lower_rad.array()).all() && (q_rad.array() <= upper_rad.array()).all() &&
         difference >= min_link_difference_rad && difference <= max_link_difference_rad;
}

bool WorkspaceBox::contains(const Eigen::Vector3d& p_P_m) const noexcept {
  return (p_P_m.array() >= min_P_m.array()).all() && (p_P_m.array() <= max_P_m.array()).all();
}

WorkspaceBox WorkspaceBox::shrunk(double margin_m) const noexcept {
  return WorkspaceBox{min_P_m.array() + margin_m, max_P_m.array() - margin_m};
}

PhantomModel phantom_premium_1_5() noexcept {
  PhantomModel model;
  model.limits.lower_rad = Eigen::Vector3d(deg(-65), deg(-25), deg(-35));
  model.limits.upper_rad = Eigen::Vector3d(deg(65), deg(105), deg(75));
  model.limits.min_link_difference_rad = deg(-65);
  model.limits.max_link_difference_rad = deg(70);
  const Eigen::Vector3d size_m(0.381, 0.267, 0.191);
  const Eigen::Vector3d center_P_m(0.0, 0.130, -0.010);
  model.workspace = WorkspaceBox{center_P_m - 0.5 * size_m, center_P_m + 0.5 * size_m};
  model.usable_margin_m = 0.030;
  return model;
}

Eigen::Vector3d phantom_tool_position(const PhantomGeometry& geometry, const Eigen::Vector3d& q_rad) noexcept {
  const double l1 = geometry.l1_m;
  const double l2 = geometry.l2_m;
  const double reach = l1 * std::cos(q_rad.y()) + l2 * std::sin(q_rad.z());
  return Eigen::Vector3d(std::sin(q_rad.x()) * reach, l2 - l2 * std::cos(q_rad.z()) + l1 * std::sin(q_rad.y()),
                         std::cos(q_rad.x()) * reach - l1);
}

Eigen::Matrix3d phantom_tool_rotation(const Eigen::Vector3d& q_rad) noexcept {
  const double c1 = std::cos(q_rad.x());
  const double s1 = std::sin(q_rad.x());
  const double c3 = std::cos(q_rad.z());
  const double s3 = std::sin(q_rad.z());
  Eigen::Matrix3d R;
  R << c1, -s1 * s3, s1 * c3,  //
      0.0, c3, s3,             //
      -s1, -c1 * s3, c1 * c3;
  return R;
}

Pose phantom_tool_pose(const PhantomGeometry& geometry, const Eigen::Vector3d& q_rad) noexcept {
  Pose X_P_tool = Pose::Identity();
  X_P_tool.linear() = phantom_tool_rotation(q_rad);
  X_P_tool.translation() = phantom_tool_position(geometry, q_rad);
  return X_P_tool;
}

Eigen::Matrix3d phantom_position_jacobian(const PhantomGeometry& geometry, const Eigen::Vector3d& q_rad) noexcept {
  const double l1 = geometry.l1_m;
  const double l2 = geometry.l2_m;
  const double c1 = std::cos(q_rad.x());
  const double s1 = std::sin(q_rad.x());
  const double c2 = std::cos(q_rad.y());
  const double s2 = std::sin(q_rad.y());
  const double c3 = std::cos(q_rad.z());
  const double s3 = std::sin(q_rad.z());
  const double reach = l1 * c2 + l2 * s3;
  Eigen::Matrix3d J;
  J << c1 * reach, -l1 * s1 * s2, l2 * s1 * c3,  //
      0.0, l1 * c2, l2 * s3,                     //
      -s1 * reach, -l1 * c1 * s2, l2 * c1 * c3;
  return J;
}

Eigen::Vector3d phantom_joint_torques(const PhantomGeometry& geometry, const Eigen::Vector3d& q_rad,
                                      const Eigen::Vector3d& force_P_N) noexcept {
  return phantom_position_jacobian(geometry, q_rad).transpose() * force_P_N;
}

std::string_view to_string(PhantomIkStatus status) noexcept {
  switch (status) {
    case PhantomIkStatus::Ok: return "ok";
    case PhantomIkStatus::OutOfReach: return "out of reach";
    case PhantomIkStatus::OnBaseAxis: return "on the base axis";
    case PhantomIkStatus::OutsideJointLimits: return "outside the joint limits";
  }
  return "unknown";
}

PhantomIkSolution phantom_inverse_kinematics(const PhantomModel& model, const Eigen::Vector3d& p_P_tool) noexcept {
  const double l1 = model.geometry.l1_m;
  const double l2 = model.geometry.l2_m;
  PhantomIkSolution result;
  if (!p_P_tool.allFinite()) return result;

  // Seen from above, the arm points from the base axis (x = 0, z = -l1) to the tool.
  const double forward = p_P_tool.z() + l1;
  const double reach = std::hypot(p_P_tool.x(), forward);
  constexpr double kAxisTolerance_m = 1e-9;
  if (reach < kAxisTolerance_m) {
    result.status = PhantomIkStatus::OnBaseAxis;
    return result;
  }
  const double theta1 = std::atan2(p_P_tool.x(), forward);

  // In the arm's vertical plane: the shoulder at the origin, the tool at (reach, height).
  const double height = p_P_tool.y() - l2;
  const double distance = std::hypot(reach, height);
  constexpr double kReachTolerance_m = 1e-12;
  if (distance > l1 + l2 + kReachTolerance_m || distance < std::abs(l1 - l2) - kReachTolerance_m ||
      distance < kAxisTolerance_m) {
    return result;  // OutOfReach
  }
  // Elbow above the shoulder-tool line: link 1 is that line's angle plus the triangle's
  // angle at the shoulder (law of cosines).
  const double cos_shoulder = std::clamp((l1 * l1 + distance * distance - l2 * l2) / (2.0 * l1 * distance), -1.0, 1.0);
  const double theta2 =
      std::remainder(std::atan2(height, reach) + std::acos(cos_shoulder), 2.0 * std::numbers::pi);
  // Link 2's absolute angle below the horizontal is theta3 - 90 degrees.
  const double link2_angle =
      std::atan2(height - l1 * std::sin(theta2), reach - l1 * std::cos(theta2));
  const double theta3 = std::remainder(link2_angle + 0.5 * std::numbers::pi, 2.0 * std::numbers::pi);

  result.q_rad = Eigen::Vector3d(theta1, theta2, theta3);
  result.status = model.limits.contains(result.q_rad) ? PhantomIkStatus::Ok : PhantomIkStatus::OutsideJointLimits;
  return result;
}

}  // namespace mhd
