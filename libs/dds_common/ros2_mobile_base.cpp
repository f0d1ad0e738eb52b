#include "dds_common/ros2_mobile_base.h"

#include "dds_common/ros2_messages.h"

#include <cmath>
#include <cstring>

namespace mhd::dds::ros2 {
namespace {

constexpr std::int64_t kFutureToleranceNs = 100'000'000;

bool finite(double v) { return std::isfinite(v); }

}  // namespace

Twist twist_of(const mhd_base_command& command) {
  Twist t{};
  t.linear.x = command.vx_mps;
  t.linear.y = -command.vz_mps;  // MHD's z is to the right, ROS's y to the left
  t.angular.z = command.omega_radps;
  return t;
}

std::int64_t stamp_ns(const Odometry& odometry) { return stamp_ns(odometry.header.stamp); }

OdometryVerdict base_state_of(const Odometry& odometry, const OdometryCheck& check, mhd_base_state& out) {
  const char* frame = odometry.header.frame_id != nullptr ? odometry.header.frame_id : "";
  const char* child = odometry.child_frame_id != nullptr ? odometry.child_frame_id : "";
  if (check.odom_frame != frame || check.base_frame != child) return OdometryVerdict::WrongFrame;
  const auto& p = odometry.pose.pose.position;
  const auto& q = odometry.pose.pose.orientation;
  const auto& v = odometry.twist.twist.linear;
  const auto& w = odometry.twist.twist.angular;
  for (const double x : {p.x, p.y, p.z, q.x, q.y, q.z, q.w, v.x, v.y, v.z, w.x, w.y, w.z}) {
    if (!finite(x)) return OdometryVerdict::NotFinite;
  }
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (std::abs(norm - 1.0) > 0.01) return OdometryVerdict::NotUnitQuaternion;
  const std::int64_t stamp = stamp_ns(odometry);
  if (odometry.header.stamp.nanosec >= 1'000'000'000u || stamp <= 0 || stamp > check.now_ns + kFutureToleranceNs) {
    return OdometryVerdict::BadStamp;
  }
  const double qx = q.x / norm;
  const double qy = q.y / norm;
  const double qz = q.z / norm;
  const double qw = q.w / norm;
  const double yaw = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
  // The twist is in base_link: turn it into the odom frame, then into MHD's world.
  const double vx_odom = std::cos(yaw) * v.x - std::sin(yaw) * v.y;
  const double vy_odom = std::sin(yaw) * v.x + std::cos(yaw) * v.y;
  out = mhd_base_state{};
  out.x_m = p.x;
  out.z_m = -p.y;
  out.heading_rad = yaw;
  out.vx_mps = vx_odom;
  out.vz_mps = -vy_odom;
  out.omega_radps = w.z;
  return OdometryVerdict::Accepted;
}

}  // namespace mhd::dds::ros2
