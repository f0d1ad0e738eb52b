#pragma once
// Position kinematics of a 3-DOF rotary delta robot (Clavel's delta, the Novint Falcon's
// family), in the device frame D: x to the user's right, y up, z out of the base towards
// the user (the Falcon SDK's axes); the origin is the centre of the base, the plane of
// the three motor axes. Derivation in docs/sim_delta.md. SI units; nothing allocates.
//
// Arm i (i = 0, 1, 2) lies in the plane spanned by the radial unit vector
// u_i = (cos phi_i, sin phi_i, 0) and z. Its motor axis is tangent to the base circle at
// R u_i; the upper arm (length a) leaves it at angle theta_i from the base plane,
// positive towards +z; the forearm (a parallelogram of length b) joins the elbow to the
// effector at p + r u_i. With S_i(theta_i) = (R - r) u_i + a (cos theta_i u_i + sin theta_i z):
//   |p - S_i(theta_i)| = b          (i = 0, 1, 2)
// forward kinematics: p is the intersection of three spheres on the +z side;
// inverse kinematics: one angle per arm, the elbow pointing away from the axis;
// Jacobian: A dp = B dtheta, rows of A = (p - S_i)^T, B = diag((p - S_i) . dS_i/dtheta_i).

#include <Eigen/Core>

#include <array>
#include <optional>

namespace mhd::sim_delta {

/// A delta's dimensions. Defaults: the Novint Falcon as libnifalcon measures it
/// (include/falcon/core/FalconGeometry.h, after Stamper's notation, PhD thesis 1997,
/// Univ. of Maryland): upper arm a = 60 mm, forearm b = 102.5 mm, leg base 40 mm and
/// effector joint 14.43 mm from the centre (the radial, "u" components), legs at
/// 105, -15 and -135 degrees (120 degrees apart, turned 15 degrees). The Falcon's
/// out-of-plane offsets (s = -23.09 mm at the base, f = -25 mm at the effector) nearly
/// cancel (1.9 mm) and are left out: this is the ideal delta closest to a Falcon.
struct DeltaGeometry {
  double base_radius_m = 0.040;
  double effector_radius_m = 0.01443;
  double upper_arm_m = 0.060;
  double forearm_m = 0.1025;
  std::array<double, 3> arm_angles_rad = {1.8325957145940461, -0.26179938779914941, -2.3561944901923448};

  /// u_i, the radial unit vector of arm i.
  [[nodiscard]] Eigen::Vector3d radial(int arm) const noexcept;
};

/// The range of every motor angle theta_i (the upper arm's stops). MHD's choice: the
/// Falcon's are not published; these keep the arms clear of the base and of the
/// folded-elbow singularity over the workspace (docs/sim_delta.md).
struct DeltaJointLimits {
  double min_rad = -0.7853981633974483;  ///< -45 degrees
  double max_rad = 1.5707963267948966;   ///< 90 degrees

  [[nodiscard]] bool contains(const Eigen::Vector3d& q_rad) const noexcept;
};

/// p_D_tool for motor angles q_rad (the effector centre), or nullopt where the three
/// forearms cannot meet (the spheres have no common point) or the inputs are not finite.
[[nodiscard]] std::optional<Eigen::Vector3d> delta_forward_kinematics(const DeltaGeometry& geometry,
                                                                      const Eigen::Vector3d& q_rad) noexcept;

/// Motor angles that put the effector at p_D_tool_m, elbows out, each wrapped to
/// (-pi, pi]; nullopt where an arm cannot reach, an angle breaks `limits`, or the input is
/// not finite. Never returns a non-finite angle.
[[nodiscard]] std::optional<Eigen::Vector3d> delta_inverse_kinematics(const DeltaGeometry& geometry,
                                                                      const DeltaJointLimits& limits,
                                                                      const Eigen::Vector3d& p_D_tool_m) noexcept;

/// J_D = d p_D_tool / d q (metres per radian) at q_rad, or nullopt where the forward
/// kinematics fails or the delta is singular there (|det A| or a |B_ii| below a relative
/// 1e-9: the forearms coplanar, or a forearm along its upper arm's motion).
[[nodiscard]] std::optional<Eigen::Matrix3d> delta_jacobian(const DeltaGeometry& geometry,
                                                            const Eigen::Vector3d& q_rad) noexcept;

/// tau = J_D^T F_D: the motor torques that hold the force F_D_N at the effector (virtual work).
[[nodiscard]] Eigen::Vector3d delta_motor_torques_Nm(const Eigen::Matrix3d& J_D, const Eigen::Vector3d& F_D_N) noexcept;

/// F_D = J_D^-T tau: the force the motor torques make at the effector, or nullopt where
/// J_D is singular.
[[nodiscard]] std::optional<Eigen::Vector3d> delta_tool_force_N(const Eigen::Matrix3d& J_D,
                                                                const Eigen::Vector3d& tau_Nm) noexcept;

}  // namespace mhd::sim_delta
