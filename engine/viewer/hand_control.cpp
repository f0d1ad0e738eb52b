#include "viewer/hand_control.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

namespace mhd::viewer {
namespace {

double depth_of(const HandCamera& camera, const Eigen::Vector3d& p_W) {
  return -(camera.X_W_camera.inverse() * p_W).z();
}

}  // namespace

double metres_per_pixel(const HandCamera& camera, double depth_m) {
  const double half_fov_rad = 0.5 * camera.fov_y_deg * std::numbers::pi / 180.0;
  return 2.0 * depth_m * std::tan(half_fov_rad) / static_cast<double>(camera.height_px);
}

HandControl::HandControl(const Eigen::Vector3d& p_W_start_m, double depth_step_m)
    : p_W_start_m_(p_W_start_m), p_W_hip_m_(p_W_start_m), depth_step_m_(depth_step_m) {}

void HandControl::move_in_depth(double distance_m, const HandCamera& camera) {
  const Eigen::Vector3d forward_W = -camera.X_W_camera.linear().col(2);
  const double depth_m = depth_of(camera, p_W_hip_m_);
  // Never back to (or behind) the eye: the drag scale would vanish or flip.
  const double moved_m =
      distance_m >= 0.0 ? distance_m : std::min(0.0, std::max(distance_m, kMinDepth_m - depth_m));
  p_W_hip_m_ += moved_m * forward_W;
}

void HandControl::apply(const InputEvent& e, const HandCamera& camera) {
  switch (e.kind) {
    case InputEvent::Kind::Press:
      if (e.button == 1) drag_from_px_ = Eigen::Vector2d(e.x_px, e.y_px);
      break;
    case InputEvent::Kind::Drag:
      if (drag_from_px_) {
        const Eigen::Vector2d to_px(e.x_px, e.y_px);
        const Eigen::Vector2d delta_px = to_px - *drag_from_px_;
        const double scale_m = metres_per_pixel(camera, std::max(depth_of(camera, p_W_hip_m_), kMinDepth_m));
        p_W_hip_m_ += scale_m * (delta_px.x() * camera.X_W_camera.linear().col(0) +
                                 delta_px.y() * camera.X_W_camera.linear().col(1));
        drag_from_px_ = to_px;
      }
      break;
    case InputEvent::Kind::Release:
      if (e.button == 1) drag_from_px_.reset();
      break;
    case InputEvent::Kind::Scroll:
      move_in_depth(e.scroll_steps * depth_step_m_, camera);
      break;
    case InputEvent::Kind::Key: {
      const int k = e.key >= 0 && e.key < 128 ? std::tolower(e.key) : e.key;
      if (k == 'w' || k == kKeyPageUp) move_in_depth(depth_step_m_, camera);
      if (k == 's' || k == kKeyPageDown) move_in_depth(-depth_step_m_, camera);
      if (k == 'r' || k == kKeyHome) p_W_hip_m_ = p_W_start_m_;
      break;
    }
  }
}

}  // namespace mhd::viewer
