#include "delta_kinematics.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <numbers>

namespace mhd::sim_delta {
namespace {

const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

/// S_i: the elbow moved in by the effector radius, the centre of arm i's forearm sphere.
Eigen::Vector3d sphere_centre(const DeltaGeometry& g, int arm, double theta_rad) {
  const Eigen::Vector3d u = g.radial(arm);
  return (g.base_radius_m - g.effector_radius_m) * u + g.upper_arm_m * (std::cos(theta_rad) * u + std::sin(theta_rad) * kZ);
}

Eigen::Vector3d sphere_centre_rate(const DeltaGeometry& g, int arm, double theta_rad) {
  const Eigen::Vector3d u = g.radial(arm);
  return g.upper_arm_m * (-std::sin(theta_rad) * u + std::cos(theta_rad) * kZ);
}

double wrap_angle(double angle_rad) {
  const double w = std::remainder(angle_rad, 2.0 * std::numbers::pi);
  return w <= -std::numbers::pi ? w + 2.0 * std::numbers::pi : w;
}

}  // namespace

Eigen::Vector3d DeltaGeometry::radial(int arm) const noexcept {
  const double phi = arm_angles_rad[static_cast<std::size_t>(arm)];
  return {std::cos(phi), std::sin(phi), 0.0};
}

bool DeltaJointLimits::contains(const Eigen::Vector3d& q_rad) const noexcept {
  return (q_rad.array() >= min_rad).all() && (q_rad.array() <= max_rad).all();
}

std::optional<Eigen::Vector3d> delta_forward_kinematics(const DeltaGeometry& g, const Eigen::Vector3d& q_rad) noexcept {
  if (!q_rad.allFinite()) return std::nullopt;
  const Eigen::Vector3d s0 = sphere_centre(g, 0, q_rad[0]);
  const Eigen::Vector3d s1 = sphere_centre(g, 1, q_rad[1]);
  const Eigen::Vector3d s2 = sphere_centre(g, 2, q_rad[2]);
  // Trilateration in the frame (e_x, e_y, e_z) of the three centres; equal radii b.
  const double d = (s1 - s0).norm();
  if (!(d > 1e-12)) return std::nullopt;
  const Eigen::Vector3d e_x = (s1 - s0) / d;
  const double i = e_x.dot(s2 - s0);
  const Eigen::Vector3d off_axis = s2 - s0 - i * e_x;
  const double j = off_axis.norm();
  if (!(j > 1e-12)) return std::nullopt;  // the centres lie on one line
  const Eigen::Vector3d e_y = off_axis / j;
  Eigen::Vector3d e_z = e_x.cross(e_y);
  if (e_z.z() < 0.0) e_z = -e_z;  // the effector hangs on the +z side of the centres' plane
  const double x = 0.5 * d;
  const double y = (i * i + j * j - 2.0 * i * x) / (2.0 * j);
  const double z_squared = g.forearm_m * g.forearm_m - x * x - y * y;
  if (!(z_squared >= 0.0)) return std::nullopt;
  const Eigen::Vector3d p = s0 + x * e_x + y * e_y + std::sqrt(z_squared) * e_z;
  if (!p.allFinite()) return std::nullopt;
  return p;
}

std::optional<Eigen::Vector3d> delta_inverse_kinematics(const DeltaGeometry& g, const DeltaJointLimits& limits,
                                                        const Eigen::Vector3d& p_D_tool_m) noexcept {
  if (!p_D_tool_m.allFinite()) return std::nullopt;
  const double a = g.upper_arm_m;
  const double b = g.forearm_m;
  Eigen::Vector3d q_rad;
  for (int arm = 0; arm < 3; ++arm) {
    // |c - a (cos t u + sin t z)|^2 = b^2 with c = p - (R - r) u gives
    // A cos t + Z sin t = K / (2a): A = c.u, Z = c.z, K = |c|^2 + a^2 - b^2.
    const Eigen::Vector3d u = g.radial(arm);
    const Eigen::Vector3d c = p_D_tool_m - (g.base_radius_m - g.effector_radius_m) * u;
    const double A = c.dot(u);
    const double Z = c.z();
    const double K = c.squaredNorm() + a * a - b * b;
    const double rho = std::hypot(A, Z);
    if (!(rho > 1e-12)) return std::nullopt;
    const double cos_offset = K / (2.0 * a * rho);
    if (!(std::abs(cos_offset) <= 1.0)) return std::nullopt;
    // rho cos(t - psi) = K / (2a); the smaller root keeps the elbow away from the axis.
    q_rad[arm] = wrap_angle(std::atan2(Z, A) - std::acos(cos_offset));
  }
  if (!q_rad.allFinite() || !limits.contains(q_rad)) return std::nullopt;
  return q_rad;
}

std::optional<Eigen::Matrix3d> delta_jacobian(const DeltaGeometry& g, const Eigen::Vector3d& q_rad) noexcept {
  const std::optional<Eigen::Vector3d> p = delta_forward_kinematics(g, q_rad);
  if (!p) return std::nullopt;
  // d/dt |p - S_i|^2 = 0:  (p - S_i) . dp = (p - S_i) . dS_i/dtheta_i dtheta_i.
  Eigen::Matrix3d A;
  Eigen::Vector3d B;
  const double scale = g.upper_arm_m * g.forearm_m;
  for (int arm = 0; arm < 3; ++arm) {
    const Eigen::Vector3d forearm = *p - sphere_centre(g, arm, q_rad[arm]);
    A.row(arm) = forearm.transpose();
    B[arm] = forearm.dot(sphere_centre_rate(g, arm, q_rad[arm]));
    if (!(std::abs(B[arm]) > 1e-9 * scale)) return std::nullopt;
  }
  if (!(std::abs(A.determinant()) > 1e-9 * g.forearm_m * g.forearm_m * g.forearm_m)) return std::nullopt;
  const Eigen::Matrix3d J = A.partialPivLu().solve(B.asDiagonal().toDenseMatrix());
  if (!J.allFinite()) return std::nullopt;
  return J;
}

Eigen::Vector3d delta_motor_torques_Nm(const Eigen::Matrix3d& J_D, const Eigen::Vector3d& F_D_N) noexcept {
  return J_D.transpose() * F_D_N;
}

std::optional<Eigen::Vector3d> delta_tool_force_N(const Eigen::Matrix3d& J_D, const Eigen::Vector3d& tau_Nm) noexcept {
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(J_D.transpose());
  if (!lu.isInvertible()) return std::nullopt;
  const Eigen::Vector3d F = lu.solve(tau_Nm);
  if (!F.allFinite()) return std::nullopt;
  return F;
}

}  // namespace mhd::sim_delta
