#include "viewer/rig_state.h"

#include <fmt/core.h>

#include <array>
#include <cmath>

namespace mhd::viewer {
namespace {

/// Empty when all n values are finite, else "display frame: <name>[i] is not finite".
std::string check_finite(const double* values, int n, const char* name) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(values[i])) return fmt::format("display frame: {}[{}] is not finite", name, i);
  }
  return {};
}

Eigen::Vector3d vec3(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

void put(std::array<double, 3>& out, const Eigen::Vector3d& v) {
  out[0] = v.x();
  out[1] = v.y();
  out[2] = v.z();
}

}  // namespace

Result<RigState, std::string> rig_state_from_frame(const DisplayFrame& f) {
  const double scalars[] = {f.timestamp_s, f.base_x_m, f.base_z_m, f.base_heading_rad};
  for (const std::string& e : {check_finite(scalars, 4, "timestamp_s/base"), check_finite(f.p_W_hip_m.data(), 3, "p_W_hip_m"),
                               check_finite(f.p_W_proxy_m.data(), 3, "p_W_proxy_m"),
                               check_finite(f.force_W_N.data(), 3, "force_W_N"),
                               check_finite(f.p_W_head_m.data(), 3, "p_W_head_m"),
                               check_finite(f.q_W_head_wxyz.data(), 4, "q_W_head_wxyz")}) {
    if (!e.empty()) return e;
  }
  const Eigen::Quaterniond q(f.q_W_head_wxyz[0], f.q_W_head_wxyz[1], f.q_W_head_wxyz[2], f.q_W_head_wxyz[3]);
  if (!(q.norm() > 1e-9)) return std::string("display frame: q_W_head_wxyz has zero norm");
  RigState s;
  s.timestamp_s = f.timestamp_s;
  s.p_W_hip_m = vec3(f.p_W_hip_m);
  s.p_W_proxy_m = vec3(f.p_W_proxy_m);
  s.force_W_N = vec3(f.force_W_N);
  s.in_contact = f.in_contact;
  s.base = BasePose{f.base_x_m, f.base_z_m, f.base_heading_rad};
  s.X_W_head = pose_from_xyz_quaternion(vec3(f.p_W_head_m), q);
  return s;
}

DisplayFrame display_frame_from_rig_state(const RigState& s) {
  DisplayFrame f;
  f.timestamp_s = s.timestamp_s;
  put(f.p_W_hip_m, s.p_W_hip_m);
  put(f.p_W_proxy_m, s.p_W_proxy_m);
  put(f.force_W_N, s.force_W_N);
  f.in_contact = s.in_contact;
  f.base_x_m = s.base.x_m;
  f.base_z_m = s.base.z_m;
  f.base_heading_rad = s.base.heading_rad;
  put(f.p_W_head_m, s.X_W_head.translation());
  const Eigen::Quaterniond q(s.X_W_head.linear());
  f.q_W_head_wxyz[0] = q.w();
  f.q_W_head_wxyz[1] = q.x();
  f.q_W_head_wxyz[2] = q.y();
  f.q_W_head_wxyz[3] = q.z();
  return f;
}

Pose head_looking_at(const Eigen::Vector3d& p_W_head_m, const Eigen::Vector3d& p_W_target_m) {
  const Eigen::Vector3d up_W = Eigen::Vector3d::UnitY();
  Eigen::Vector3d x = p_W_target_m - p_W_head_m;
  if (x.cross(up_W).norm() < 1e-9 * std::max(1.0, x.norm())) x = -Eigen::Vector3d::UnitZ();
  x.normalize();
  const Eigen::Vector3d z = x.cross(up_W).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Pose X = Pose::Identity();
  X.linear().col(0) = x;
  X.linear().col(1) = y;
  X.linear().col(2) = z;
  X.translation() = p_W_head_m;
  return X;
}

}  // namespace mhd::viewer
