#include "viewer/hand_session.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <thread>

namespace mhd::viewer {
namespace {

constexpr double kStartGap_m = 0.10;
constexpr double kStartSearch_m = 10.0;
constexpr double kStartSearchStep_m = 0.005;

/// 10 cm in front of the first surface on the camera's centre line (see HandSessionOptions).
Eigen::Vector3d pick_start(const CompiledScene& scene, const HandCamera& camera) {
  const Eigen::Vector3d p_W_eye = camera.X_W_camera.translation();
  const Eigen::Vector3d forward_W = -camera.X_W_camera.linear().col(2);
  for (double d_m = HandControl::kMinDepth_m; d_m < kStartSearch_m; d_m += kStartSearchStep_m) {
    if (HandSimulation::start_blocked(scene, p_W_eye + d_m * forward_W)) {
      return p_W_eye + std::max(HandControl::kMinDepth_m, d_m - kStartGap_m) * forward_W;
    }
  }
  return p_W_eye + 1.0 * forward_W;
}

std::string start_error(const Eigen::Vector3d& p_W_start_m, const std::string& why) {
  return fmt::format("the HIP cannot start at ({}, {}, {}) m: it {}; the proxy must start in free space",
                     p_W_start_m.x(), p_W_start_m.y(), p_W_start_m.z(), why);
}

}  // namespace

std::string hand_overlay_text(const HandSample& s, const CompiledScene& scene, double force_scale_m_per_N) {
  const bool named = s.contact_object >= 0 && static_cast<std::size_t>(s.contact_object) < scene.object_names.size();
  const std::string contact =
      s.in_contact ? (named ? fmt::format("yes ({})", scene.object_names[static_cast<std::size_t>(s.contact_object)])
                            : std::string("yes"))
                   : std::string("no");
  const Eigen::Vector3d& h = s.p_W_hip_m;
  return fmt::format(
      "force {:.2f} N (max {:.1f})   penetration {:.1f} mm   contact {}\n"
      "HIP ({:.3f}, {:.3f}, {:.3f}) m   t {:.2f} s\n"
      "force arrow: 1 N = {:.0f} mm\n"
      "drag: move in the screen plane   wheel, W/S, PgUp/PgDn: depth   R: reset   Esc: quit",
      s.force_W_N.norm(), scene.proxy.max_force_N, 1e3 * s.penetration_m, contact, h.x(), h.y(), h.z(), s.t_s,
      1e3 * force_scale_m_per_N);
}

struct HandSession::Impl {
  HandSessionOptions options;
  const CompiledScene* compiled = nullptr;
  std::unique_ptr<StereoViewer> viewer;
  HandCamera camera;
  EyeView view;
  std::optional<HandControl> control;
  std::optional<HandSimulation> simulation;
  std::string overlay;
};

namespace {

/// Steps the simulation once per drawn frame and hands its result to the viewer.
class HandStateSource final : public StateSource {
 public:
  explicit HandStateSource(HandSession::Impl& impl) : impl_(impl) {}
  [[nodiscard]] std::optional<RigState> latest() override {
    if (!impl_.simulation) return std::nullopt;
    const HandSample& s = impl_.simulation->advance(impl_.control->p_W_hip_m(), impl_.options.frame_period_s);
    impl_.overlay = hand_overlay_text(s, *impl_.compiled, impl_.options.view.force_scale_m_per_N);
    impl_.viewer->set_overlay_text(impl_.overlay);
    for (std::size_t i = 0; i < impl_.compiled->motions.size(); ++i) {
      if (impl_.compiled->motions[i]) impl_.viewer->set_object_pose(i, impl_.simulation->world().pose(static_cast<int>(i)));
    }
    RigState state;
    state.timestamp_s = s.t_s;
    state.p_W_hip_m = s.p_W_hip_m;
    state.p_W_proxy_m = s.p_W_proxy_m;
    state.force_W_N = s.force_W_N;
    state.in_contact = s.in_contact;
    return state;
  }

 private:
  HandSession::Impl& impl_;
};

}  // namespace

HandSession::HandSession(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HandSession::~HandSession() = default;

Result<std::unique_ptr<HandSession>, std::string> HandSession::open(const ViewerScene& scene,
                                                                    const CompiledScene& compiled,
                                                                    HandSessionOptions options) {
  if (!(options.frame_period_s > 0.0) || !(options.depth_step_m > 0.0)) {
    return fmt::format("frame period and depth step must be > 0, got {} s and {} m", options.frame_period_s,
                       options.depth_step_m);
  }
  ViewerOptions& view = options.view;
  view.stereo = false;
  view.show_device = false;
  view.overlay_text = true;
  view.view_point = ViewPoint::Observer;

  // A given start is refused before any window opens.
  if (options.p_W_start_m) {
    if (const auto why = HandSimulation::start_blocked(compiled, *options.p_W_start_m)) {
      return start_error(*options.p_W_start_m, *why);
    }
  }
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  impl->compiled = &compiled;
  Result<std::unique_ptr<StereoViewer>, std::string> opened =
      StereoViewer::open(scene, view, std::make_shared<HandStateSource>(*impl));
  if (!opened.ok()) return opened.error();
  impl->viewer = std::move(opened).value();
  const ViewGeometry geometry{view.ipd_m, view.fov_deg, view.near_m, view.far_m, view.width, view.height, false};
  impl->view = eye_views(impl->viewer->default_head(), geometry).front();
  impl->camera = HandCamera{impl->view.X_W_camera, view.fov_deg, view.height};

  const Eigen::Vector3d p_W_start_m = options.p_W_start_m ? *options.p_W_start_m : pick_start(compiled, impl->camera);
  if (const auto why = HandSimulation::start_blocked(compiled, p_W_start_m)) return start_error(p_W_start_m, *why);
  impl->control.emplace(p_W_start_m, options.depth_step_m);
  impl->simulation.emplace(compiled, p_W_start_m);
  Impl* raw = impl.get();
  impl->viewer->set_input_handler([raw](const InputEvent& e) { raw->control->apply(e, raw->camera); });
  return std::unique_ptr<HandSession>(new HandSession(std::move(impl)));
}

void HandSession::inject(const InputEvent& event) { impl_->viewer->inject(event); }
bool HandSession::frame() { return impl_->viewer->frame(); }
RgbaImage HandSession::frame_and_capture() { return impl_->viewer->frame_and_capture(); }

std::string HandSession::run(const std::vector<ScriptedEvent>& script, const std::atomic<bool>& stop) {
  const ViewerOptions& o = impl_->options.view;
  using Clock = std::chrono::steady_clock;
  const auto period = o.max_frame_rate_Hz > 0.0 ? std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(1.0 / o.max_frame_rate_Hz))
                                                : Clock::duration::zero();
  auto next = Clock::now();
  auto event = script.begin();
  while (!stop.load(std::memory_order_relaxed)) {
    if (period > Clock::duration::zero()) {
      std::this_thread::sleep_until(next);
      next = std::max(next + period, Clock::now() - period);  // no burst after a stall
    }
    const std::uint64_t f = frames_drawn();
    for (; event != script.end() && static_cast<std::uint64_t>(event->frame) <= f; ++event) inject(event->event);
    const bool last = o.frames > 0 && f + 1 >= static_cast<std::uint64_t>(o.frames);
    if (last && !o.screenshot_png.empty()) return write_png(o.screenshot_png, frame_and_capture());
    if (!frame() || last) break;
  }
  return {};
}

const HandSample& HandSession::sample() const { return impl_->simulation->sample(); }
const HandCamera& HandSession::camera() const { return impl_->camera; }
const EyeView& HandSession::view() const { return impl_->view; }
const Eigen::Vector3d& HandSession::p_W_start_m() const { return impl_->control->p_W_start_m(); }
std::uint64_t HandSession::frames_drawn() const { return impl_->viewer->frames_drawn(); }
const std::string& HandSession::overlay_text() const { return impl_->overlay; }

}  // namespace mhd::viewer
