#include "viewer/stereo_views.h"

#include <cmath>
#include <numbers>

namespace mhd::viewer {

Pose camera_from_head(const Pose& X_W_head, double offset_right_m) {
  Eigen::Matrix3d R_H_C;
  R_H_C.col(0) = Eigen::Vector3d::UnitZ();
  R_H_C.col(1) = Eigen::Vector3d::UnitY();
  R_H_C.col(2) = -Eigen::Vector3d::UnitX();
  Pose X_H_C = Pose::Identity();
  X_H_C.linear() = R_H_C;
  X_H_C.translation() = Eigen::Vector3d(0.0, 0.0, offset_right_m);
  return X_W_head * X_H_C;
}

Eigen::Matrix4d perspective(double fov_y_deg, double aspect, double near_m, double far_m) {
  const double f = 1.0 / std::tan(0.5 * fov_y_deg * std::numbers::pi / 180.0);
  Eigen::Matrix4d P = Eigen::Matrix4d::Zero();
  P(0, 0) = f / aspect;
  P(1, 1) = f;
  P(2, 2) = (far_m + near_m) / (near_m - far_m);
  P(2, 3) = 2.0 * far_m * near_m / (near_m - far_m);
  P(3, 2) = -1.0;
  return P;
}

std::vector<EyeView> eye_views(const Pose& X_W_head, const ViewGeometry& g) {
  std::vector<EyeView> views;
  const int eye_width = g.stereo ? g.width / 2 : g.width;
  const double aspect = static_cast<double>(eye_width) / static_cast<double>(g.height);
  const Eigen::Matrix4d P = perspective(g.fov_y_deg, aspect, g.near_m, g.far_m);
  auto add = [&](Eye eye, double offset_m, int x) {
    views.push_back(EyeView{eye, camera_from_head(X_W_head, offset_m), P, x, eye_width, g.height});
  };
  if (g.stereo) {
    add(Eye::Left, -0.5 * g.ipd_m, 0);
    add(Eye::Right, 0.5 * g.ipd_m, eye_width);
  } else {
    add(Eye::Centre, 0.0, 0);
  }
  return views;
}

bool project_to_pixel(const EyeView& view, const Eigen::Vector3d& p_W, Eigen::Vector2d& pixel) {
  const Eigen::Vector3d p_C = view.X_W_camera.inverse() * p_W;
  if (p_C.z() >= 0.0) return false;
  const Eigen::Vector4d clip = view.projection * p_C.homogeneous();
  const double ndc_x = clip.x() / clip.w();
  const double ndc_y = clip.y() / clip.w();
  pixel.x() = view.viewport_x + 0.5 * (ndc_x + 1.0) * view.width;
  pixel.y() = 0.5 * (1.0 - ndc_y) * view.height;
  return true;
}

}  // namespace mhd::viewer
