#pragma once
// Kinematics of the PHANToM Premium 1.5 (three actuated joints), in its own frame P:
// x to the device's right, y up, z towards the user; the origin is the tool point (HIP)
// with every joint at 0 (link 1 horizontal, pointing at the user; link 2 hanging down).
// The shoulder (joint 2 axis) is then at (0, l2, -l1). Angles: theta1 turns the arm about
// P's y axis, theta2 raises link 1 above the horizontal, theta3 swings link 2 from
// vertical towards the user. SI units throughout; nothing here allocates.
//
// Forward kinematics (thesis eq. 4.5, derived again, see docs/kinematics.md):
//   K = l1 cos(theta2) + l2 sin(theta3)          horizontal reach from the base axis
//   p_P_tool = ( sin(theta1) K,  l2 - l2 cos(theta3) + l1 sin(theta2),  cos(theta1) K - l1 )
//   R_P_tool = Ry(theta1) Rx(-theta3)
//            = [ c1  -s1 s3   s1 c3 ]
//              [ 0    c3      s3    ]
//              [-s1  -c1 s3   c1 c3 ]
// The tool frame is the end of link 2: x along the elbow axis, y from the tool point up
// link 2 towards the elbow. The thesis prints entry (1,3) as -s1 s3, (3,1) as +s1 and
// (3,3) as -c1 c3; as printed the matrix is neither orthogonal nor of determinant 1.
// Its columns 1-2 and row 2 fix the rest: the only rotation with them is the one above.

#include "geometry/pose.h"

#include <Eigen/Core>

#include <string_view>

namespace mhd {

/// Link lengths (SensAble's figure for the Premium 1.5, used by OpenHaptics).
struct PhantomGeometry {
  double l1_m = 0.20955;
  double l2_m = 0.20955;
};

/// Joint limits of the simulated device: a box on (theta1, theta2, theta3) plus a limit on
/// the links' relative angle theta3 - theta2 (the parallelogram's range; the elbow's inner
/// angle is 90 degrees plus it, 180 degrees being a straight, singular arm).
struct PhantomJointLimits {
  Eigen::Vector3d lower_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d upper_rad = Eigen::Vector3d::Zero();
  double min_link_difference_rad = 0.0;  ///< lower bound of theta3 - theta2
  double max_link_difference_rad = 0.0;  ///< upper bound of theta3 - theta2

  [[nodiscard]] bool contains(const Eigen::Vector3d& q_rad) const noexcept;
};

/// Axis-aligned box in the device frame P.
struct WorkspaceBox {
  Eigen::Vector3d min_P_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d max_P_m = Eigen::Vector3d::Zero();

  [[nodiscard]] bool contains(const Eigen::Vector3d& p_P_m) const noexcept;
  [[nodiscard]] Eigen::Vector3d size_m() const noexcept { return max_P_m - min_P_m; }
  [[nodiscard]] Eigen::Vector3d center_P_m() const noexcept { return 0.5 * (min_P_m + max_P_m); }
  /// The box moved in by `margin_m` on every side.
  [[nodiscard]] WorkspaceBox shrunk(double margin_m) const noexcept;
};

/// A device: geometry, joint limits, the nominal workspace box and the margin that makes
/// the usable workspace (where the HIP may go before the base has to move).
struct PhantomModel {
  PhantomGeometry geometry;
  PhantomJointLimits limits;
  WorkspaceBox workspace;
  double usable_margin_m = 0.0;

  [[nodiscard]] WorkspaceBox usable_workspace() const noexcept { return workspace.shrunk(usable_margin_m); }
};

/// The PHANToM Premium 1.5 as MHD models it. Workspace 381 x 267 x 191 mm (W x H x D,
/// SensAble's figure) centred at (0, 130, -10) mm in P: placed so that the whole box is
/// reachable within the joint limits (theta1 +-65 deg, theta2 -25..105 deg, theta3
/// -35..75 deg, theta3 - theta2 -65..70 deg). The thesis gives neither placement nor
/// limits; these are MHD's. Usable workspace: 30 mm inside the box on every side
/// (321 x 207 x 131 mm), leaving the base time to follow before the arm runs out.
[[nodiscard]] PhantomModel phantom_premium_1_5() noexcept;

/// p_P_tool: the tool point in P.
[[nodiscard]] Eigen::Vector3d phantom_tool_position(const PhantomGeometry& geometry, const Eigen::Vector3d& q_rad) noexcept;

/// R_P_tool = Ry(theta1) Rx(-theta3).
[[nodiscard]] Eigen::Matrix3d phantom_tool_rotation(const Eigen::Vector3d& q_rad) noexcept;

/// X_P_tool.
[[nodiscard]] Pose phantom_tool_pose(const PhantomGeometry& geometry, const Eigen::Vector3d& q_rad) noexcept;

/// J_P = d p_P_tool / d q (3x3, metres per radian):
///   [ c1 K   -l1 s1 s2   l2 s1 c3 ]
///   [ 0       l1 c2      l2 s3    ]
///   [ -s1 K  -l1 c1 s2   l2 c1 c3 ]
/// Singular when K = 0 (tool on the base axis) or cos(theta2 - theta3) = 0 (links aligned).
[[nodiscard]] Eigen::Matrix3d phantom_position_jacobian(const PhantomGeometry& geometry, const Eigen::Vector3d& q_rad) noexcept;

/// Joint torques that make the force `force_P_N` (in P) at the tool: tau = J_P^T F.
[[nodiscard]] Eigen::Vector3d phantom_joint_torques(const PhantomGeometry& geometry, const Eigen::Vector3d& q_rad,
                                                    const Eigen::Vector3d& force_P_N) noexcept;

enum class PhantomIkStatus {
  Ok,
  OutOfReach,          ///< farther from the shoulder than l1 + l2 (or nearer than |l1 - l2|)
  OnBaseAxis,          ///< on theta1's axis, where theta1 is undefined
  OutsideJointLimits,  ///< reachable geometrically, but q breaks a joint limit (q is set)
};

[[nodiscard]] std::string_view to_string(PhantomIkStatus status) noexcept;

struct PhantomIkSolution {
  PhantomIkStatus status = PhantomIkStatus::OutOfReach;
  Eigen::Vector3d q_rad = Eigen::Vector3d::Zero();  ///< set for Ok and OutsideJointLimits
  [[nodiscard]] bool ok() const noexcept { return status == PhantomIkStatus::Ok; }
};

/// Joint angles that put the tool at p_P_tool, in closed form: theta1 from the direction
/// seen from above, then the two-link planar problem with the elbow above the line from
/// the shoulder to the tool (the device's only assembly). Used by the simulated device.
[[nodiscard]] PhantomIkSolution phantom_inverse_kinematics(const PhantomModel& model, const Eigen::Vector3d& p_P_tool) noexcept;

}  // namespace mhd
