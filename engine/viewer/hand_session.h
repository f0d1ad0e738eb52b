#pragma once
// `mhd try`'s window (docs/viewer.md "Try it by hand"): a mono view of the scene from a
// fixed camera, the HIP moved by the mouse and keys (HandControl), the engine's proxy
// stepped at 1 kHz on the compiled scene (HandSimulation), and the HIP, the proxy (red
// in contact), the force arrow and a text overlay drawn. The scene's plugins and rig are
// never opened: nothing but the scene's objects and materials is used.
//
// Per frame: the window's (or injected) events move the HIP target; the next frame
// steps a frame period of ticks towards it and draws the result.

#include "viewer/hand_control.h"
#include "viewer/hand_simulation.h"
#include "viewer/input_script.h"
#include "viewer/stereo_viewer.h"

#include <memory>
#include <optional>
#include <string>

namespace mhd::viewer {

struct HandSessionOptions {
  ViewerOptions view;  ///< mono, no device body, overlay on: open() sets those
  /// Where the HIP starts; nullopt: 10 cm in front of the first surface on the view's
  /// centre line (1 m in front of the camera when none is within 10 m).
  std::optional<Eigen::Vector3d> p_W_start_m;
  double frame_period_s = 1.0 / 60.0;  ///< simulated time per drawn frame
  double depth_step_m = 0.01;          ///< per wheel notch or W/S key
};

class HandSession {
 public:
  /// `compiled` is `scene` compiled; both must outlive the session. The error says why
  /// there is no session: a blocked start point, bad options, no display, ...
  [[nodiscard]] static Result<std::unique_ptr<HandSession>, std::string> open(const ViewerScene& scene,
                                                                              const CompiledScene& compiled,
                                                                              HandSessionOptions options);
  ~HandSession();
  HandSession(const HandSession&) = delete;
  HandSession& operator=(const HandSession&) = delete;

  /// Queues an event in the viewer's event queue, as the window would.
  void inject(const InputEvent& event);
  /// Draws one frame; false once the window was closed.
  bool frame();
  [[nodiscard]] RgbaImage frame_and_capture();
  /// Draws until options.view.frames (then its screenshot), the window closes or `stop`,
  /// injecting each scripted event just before the frame it names is drawn. Empty, or
  /// why the screenshot failed.
  [[nodiscard]] std::string run(const std::vector<ScriptedEvent>& script, const std::atomic<bool>& stop);

  [[nodiscard]] const HandSample& sample() const;
  [[nodiscard]] const HandCamera& camera() const;
  [[nodiscard]] const EyeView& view() const;
  [[nodiscard]] const Eigen::Vector3d& p_W_start_m() const;
  [[nodiscard]] std::uint64_t frames_drawn() const;
  [[nodiscard]] const std::string& overlay_text() const;

  struct Impl;

 private:
  explicit HandSession(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// The overlay's lines for a sample (force, penetration, contact; HIP; legend and keys).
[[nodiscard]] std::string hand_overlay_text(const HandSample& sample, const CompiledScene& scene,
                                            double force_scale_m_per_N);

}  // namespace mhd::viewer
