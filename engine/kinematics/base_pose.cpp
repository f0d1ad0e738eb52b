#include "kinematics/base_pose.h"

#include <cmath>
#include <numbers>

namespace mhd {

namespace {

// sin(x)/x, with its Taylor series near 0 where the quotient loses precision.
double sinc(double x) noexcept {
  if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
  return std::sin(x) / x;
}

}  // namespace

double wrap_angle(double angle_rad) noexcept {
  double a = std::remainder(angle_rad, 2.0 * std::numbers::pi);  // [-pi, pi]
  if (a <= -std::numbers::pi) a += 2.0 * std::numbers::pi;
  return a;
}

Pose pose_from_base(const BasePose& base) noexcept {
  Pose X_WB = Pose::Identity();
  X_WB.linear() = Eigen::AngleAxisd(base.heading_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  X_WB.translation() = Eigen::Vector3d(base.x_m, 0.0, base.z_m);
  return X_WB;
}

BasePose base_from_pose(const Pose& X_WB) noexcept {
  // B's x axis in W is (cos h, 0, -sin h) for a level pose.
  const Eigen::Vector3d x_axis = X_WB.linear().col(0);
  return BasePose{X_WB.translation().x(), X_WB.translation().z(), std::atan2(-x_axis.z(), x_axis.x())};
}

BasePose integrate_twist(const BasePose& start, const BaseTwist& twist_B, double dt_s) noexcept {
  // World velocity is Ry(heading(t)) v_B with heading(t) = h0 + omega t. Integrating cos and
  // sin of a linear angle over [0, dt] gives dt * sinc(omega dt / 2) at the mid heading.
  const double half_turn = 0.5 * twist_B.omega_radps * dt_s;
  const double mid = start.heading_rad + half_turn;
  const double scale = dt_s * sinc(half_turn);
  const double c = std::cos(mid);
  const double s = std::sin(mid);
  return BasePose{start.x_m + scale * (c * twist_B.vx_mps + s * twist_B.vz_mps),
                  start.z_m + scale * (-s * twist_B.vx_mps + c * twist_B.vz_mps),
                  start.heading_rad + twist_B.omega_radps * dt_s};
}

Eigen::Vector2d world_to_base_xz(double heading_rad, double dx_m, double dz_m) noexcept {
  const double c = std::cos(heading_rad);
  const double s = std::sin(heading_rad);
  return Eigen::Vector2d(c * dx_m - s * dz_m, s * dx_m + c * dz_m);
}

}  // namespace mhd
