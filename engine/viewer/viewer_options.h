#pragma once
// How the viewer draws: stereo or mono, eye separation and field of view, the window or
// offscreen image size, and an optional screenshot. Plain data; check() says what is wrong.

#include <Eigen/Core>

#include <optional>
#include <string>

namespace mhd::viewer {

/// Where the eyes are: at the tracked head (an HMD), or at a fixed observer pose that
/// looks at the scene and shows the user's head as a model (a desktop overview).
enum class ViewPoint { Head, Observer };

struct ViewerOptions {
  bool stereo = true;          ///< side by side, left eye in the left half
  double ipd_m = 0.064;        ///< interpupillary distance
  double fov_deg = 90.0;       ///< per-eye vertical field of view
  int width = 1600;            ///< the whole window or image (both eyes), pixels
  int height = 800;
  bool offscreen = false;      ///< render into a pbuffer (still needs an X display, e.g. Xvfb)
  std::string screenshot_png;  ///< written after `frames` frames when not empty
  int frames = 0;              ///< frames to render before the screenshot and exit; 0: until closed
  double max_frame_rate_Hz = 60.0;  ///< run() paces itself to this; 0: as fast as it draws
  ViewPoint view_point = ViewPoint::Head;
  bool show_grid = true;       ///< a 1 m floor grid (10 cm minor lines)
  bool show_rig = true;        ///< HIP, proxy, force, base, arm, head, workspace (when a state is there)
  bool show_device = true;     ///< base, arm, head and workspace; false: HIP, proxy and force only
  bool overlay_text = false;   ///< lines of text over the image (StereoViewer::set_overlay_text)
  double force_scale_m_per_N = 0.05;  ///< arrow length per newton
  double near_m = 0.02;
  double far_m = 100.0;
  /// The head used until a state arrives (and by the observer): nullopt picks one that
  /// looks at the scene's objects from 1.7 m high.
  std::optional<Eigen::Vector3d> default_head_m;
  std::optional<Eigen::Vector3d> look_at_m;
  std::string window_title = "MHD viewer";

  /// Empty when usable, else the first problem ("ipd_m must be in [0, 0.2], got 0.5").
  [[nodiscard]] std::string check() const;
  /// Pixels of one eye's view: half the width in stereo.
  [[nodiscard]] int eye_width() const { return stereo ? width / 2 : width; }
};

}  // namespace mhd::viewer
