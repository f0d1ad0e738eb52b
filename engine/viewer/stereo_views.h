#pragma once
// The per-eye cameras of a head pose. Each eye sits ipd/2 to the left or right of the
// head (along the head's z, its right) and looks along the head's x with parallel
// axes and a symmetric frustum, as an HMD's eye displays do. The camera frame C is
// OpenGL's: x right, y up, looking along -z.

#include "geometry/pose.h"

#include <Eigen/Core>

#include <vector>

namespace mhd::viewer {

enum class Eye { Left, Right, Centre };

struct EyeView {
  Eye eye = Eye::Centre;
  Pose X_W_camera = Pose::Identity();       ///< the eye's camera frame in the world
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();  ///< OpenGL clip from camera
  int viewport_x = 0;  ///< left edge of the eye's viewport in the image, pixels
  int width = 0;
  int height = 0;
};

struct ViewGeometry {
  double ipd_m = 0.064;
  double fov_y_deg = 90.0;
  double near_m = 0.02;
  double far_m = 100.0;
  int width = 1600;  ///< the whole image
  int height = 800;
  bool stereo = true;
};

/// The camera frame of an eye at the head: C's x = H's z, C's y = H's y, C's z = -H's x.
[[nodiscard]] Pose camera_from_head(const Pose& X_W_head, double offset_right_m);

/// OpenGL perspective projection (gluPerspective).
[[nodiscard]] Eigen::Matrix4d perspective(double fov_y_deg, double aspect, double near_m, double far_m);

/// Left then right eye (stereo) or the centre eye (mono).
[[nodiscard]] std::vector<EyeView> eye_views(const Pose& X_W_head, const ViewGeometry& geometry);

/// Where p_W lands in the whole image, in `pixel` (x right from the image's left edge,
/// y down from its top). False, leaving `pixel` alone, when the point is behind the eye.
[[nodiscard]] bool project_to_pixel(const EyeView& view, const Eigen::Vector3d& p_W, Eigen::Vector2d& pixel);

}  // namespace mhd::viewer
