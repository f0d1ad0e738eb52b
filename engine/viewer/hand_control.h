#pragma once
// The hand interaction point (HIP) as the mouse and keys move it in `mhd try`
// (docs/viewer.md "Try it by hand"): a left-button drag moves it in the plane parallel
// to the screen through where it is, so it stays under the pointer's motion; the wheel
// (up: away from the user), W/S and PageUp/PageDown move it along the view direction;
// R or Home puts it back where it started. Pure math on the camera, no OSG.

#include "geometry/pose.h"
#include "viewer/input_event.h"

#include <Eigen/Core>

#include <optional>

namespace mhd::viewer {

/// The view the pointer moves in: OpenGL camera frame (x right, y up, looking along -z).
struct HandCamera {
  Pose X_W_camera = Pose::Identity();
  double fov_y_deg = 60.0;
  int height_px = 800;
};

class HandControl {
 public:
  /// Nearest the HIP may come to the camera, so a drag keeps a finite scale.
  static constexpr double kMinDepth_m = 0.05;

  HandControl(const Eigen::Vector3d& p_W_start_m, double depth_step_m);

  void apply(const InputEvent& event, const HandCamera& camera);

  [[nodiscard]] const Eigen::Vector3d& p_W_hip_m() const { return p_W_hip_m_; }
  [[nodiscard]] const Eigen::Vector3d& p_W_start_m() const { return p_W_start_m_; }

 private:
  void move_in_depth(double distance_m, const HandCamera& camera);

  Eigen::Vector3d p_W_start_m_;
  Eigen::Vector3d p_W_hip_m_;
  double depth_step_m_;
  std::optional<Eigen::Vector2d> drag_from_px_;  ///< where the left button last was, while held
};

/// Metres that one pixel spans at `depth_m` in front of a camera of this field of view.
[[nodiscard]] double metres_per_pixel(const HandCamera& camera, double depth_m);

}  // namespace mhd::viewer
