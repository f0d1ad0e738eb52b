#pragma once
// The viewer: a scene XML's objects, a floor grid and the rig state, drawn with
// OpenSceneGraph as two side-by-side eye views from the tracked head (stereo, for an
// HMD) or one view (mono), in a window or offscreen (a pbuffer; X is still needed,
// e.g. Xvfb). Every OSG call happens in the thread that opened the viewer.
//
//   auto opened = StereoViewer::open(scene, rig, options, source);
//   if (!opened.viewer) fail(opened.error);
//   std::string error = opened.viewer->run(stop);  // frames, screenshot
//
// The state comes from a StateSource (state_source.h), asked once per frame.

#include "diagnostics/result.h"
#include "kinematics/rig.h"
#include "scene/scene_description.h"
#include "viewer/input_event.h"
#include "viewer/png_image.h"
#include "viewer/state_source.h"
#include "viewer/stereo_views.h"
#include "viewer/viewer_options.h"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mhd::viewer {

/// A scene ready to view: the description and, when its rig frames (or those of a
/// separate rig file) define the chain, the rig that places the device and workspace.
struct ViewerScene {
  SceneDescription scene;
  std::optional<Rig> rig;
  std::vector<std::string> notes;  ///< e.g. "scene has no rig frames: the workspace box is not drawn"
};

/// Reads `scene_file`; rig frames come from `rig_file` when given, else from the scene.
/// A scene without rig frames is fine (no workspace box); incomplete ones are errors,
/// each "file:line: error: ..." as the reader gives them.
[[nodiscard]] Result<ViewerScene, std::vector<std::string>> load_viewer_scene(const std::filesystem::path& scene_file,
                                                  const std::optional<std::filesystem::path>& rig_file = std::nullopt);

class StereoViewer {
 public:
  /// `source` may be null (nothing but the scene is drawn). The error says why there is
  /// no viewer: bad options, no display, a mesh, no GL context.
  [[nodiscard]] static Result<std::unique_ptr<StereoViewer>, std::string> open(const ViewerScene& scene, const ViewerOptions& options,
                                       std::shared_ptr<StateSource> source);
  ~StereoViewer();
  StereoViewer(const StereoViewer&) = delete;
  StereoViewer& operator=(const StereoViewer&) = delete;

  /// Draws one frame with the source's latest state. False once the window was closed.
  bool frame();
  /// Draws one frame and returns it (both eyes, top row first).
  [[nodiscard]] RgbaImage frame_and_capture();
  /// Draws until options.frames frames are done (then writes options.screenshot_png when
  /// set), the window is closed or `stop` is set. Empty, or why the screenshot failed.
  [[nodiscard]] std::string run(const std::atomic<bool>& stop);

  /// Mouse and key events of the window (and injected ones) go to `handler` during the
  /// next frame's event traversal, before the state is drawn.
  void set_input_handler(std::function<void(const InputEvent&)> handler);
  /// Queues `event` in the viewer's event queue as if the window had sent it.
  void inject(const InputEvent& event);
  /// The text over the image (with options.overlay_text), from the next frame on.
  void set_overlay_text(const std::string& text);
  /// Also draws another rig from `source` (a second user's hand, proxy, force, base and
  /// head, e.g. another haptic process's rig state over DDS), from the next frame on. The
  /// view stays with the first source's head. A null source is ignored.
  void add_rig(std::shared_ptr<StateSource> source);
  /// Draws scene object `object` (its index in the scene's objects) at X_WO from the next
  /// frame on: a moving object. An index the scene does not have is ignored.
  void set_object_pose(std::size_t object, const Pose& X_WO);

  /// The eye views of the last frame (for tests: where a world point lands in the image).
  [[nodiscard]] const std::vector<EyeView>& views() const;
  [[nodiscard]] std::uint64_t frames_drawn() const;
  /// The head pose used while no state has arrived (and by the observer view point).
  [[nodiscard]] const Pose& default_head() const;

 private:
  struct Impl;
  explicit StereoViewer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace mhd::viewer
