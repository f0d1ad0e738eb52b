#include "viewer/stereo_viewer.h"

#include "scene_xml/scene_reader.h"
#include "viewer/display_check.h"
#include "viewer/hud_overlay.h"
#include "viewer/input_forwarding.h"
#include "viewer/osg_convert.h"
#include "viewer/rig_graph.h"
#include "viewer/scene_graph.h"

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <osg/Camera>
#include <osg/GraphicsContext>
#include <osg/Image>
#include <osgViewer/Viewer>

#include <algorithm>
#include <chrono>
#include <thread>
#include <cmath>
#include <cstring>
#include <numbers>
#include <utility>

namespace mhd::viewer {
// Named, not anonymous: StereoViewer::Impl holds it, and GCC warns (-Wsubobject-linkage)
// when a class outside the main file of a unity batch holds an internal-linkage type.
namespace stereo_viewer_detail {

/// Reads the camera's viewport into `image` after the camera has drawn, when armed.
class CaptureCallback : public osg::Camera::DrawCallback {
 public:
  void operator()(osg::RenderInfo& render_info) const override {
    const osg::Camera* camera = render_info.getCurrentCamera();
    if (!armed || camera == nullptr || camera->getViewport() == nullptr) return;
    const osg::Viewport* vp = camera->getViewport();
    image->readPixels(static_cast<int>(vp->x()), static_cast<int>(vp->y()), static_cast<int>(vp->width()),
                      static_cast<int>(vp->height()), GL_RGBA, GL_UNSIGNED_BYTE);
  }
  bool armed = false;
  osg::ref_ptr<osg::Image> image = make_ref<osg::Image>();
};

}  // namespace stereo_viewer_detail

using stereo_viewer_detail::CaptureCallback;

namespace {

/// Looks at the objects from 1.7 m high, far enough back to see them whole.
Pose pick_default_head(const Eigen::AlignedBox3d& bounds, const ViewerOptions& options) {
  const Eigen::Vector3d target = options.look_at_m ? *options.look_at_m
                                 : bounds.isEmpty() ? Eigen::Vector3d(0.0, 1.0, 0.0)
                                                    : bounds.center();
  if (options.default_head_m) return head_looking_at(*options.default_head_m, target);
  const double radius = bounds.isEmpty() ? 0.5 : 0.5 * bounds.diagonal().norm();
  const double half_fov_rad = 0.5 * options.fov_deg * std::numbers::pi / 180.0;
  const double distance = std::max(1.0, 1.3 * radius / std::tan(half_fov_rad));
  const Eigen::Vector3d head(target.x(), 1.7, target.z() + distance);
  return head_looking_at(head, target);
}

}  // namespace

Result<ViewerScene, std::vector<std::string>> load_viewer_scene(const std::filesystem::path& scene_file,
                                                              const std::optional<std::filesystem::path>& rig_file) {
  std::vector<std::string> errors;
  Result<SceneDescription> read = read_scene_file(scene_file);
  for (const Diagnostic& d : read.diagnostics()) errors.push_back(d.to_string());
  if (!read.ok()) return errors;
  ViewerScene viewer_scene{std::move(*read), std::nullopt, {}};

  std::vector<FrameDescription> frames = viewer_scene.scene.rig_frames;
  if (rig_file) {
    Result<SceneDescription> rig_read = read_scene_file(*rig_file);
    for (const Diagnostic& d : rig_read.diagnostics()) errors.push_back(d.to_string());
    if (!rig_read.ok()) return errors;
    frames = rig_read->rig_frames;
    if (frames.empty()) {
      errors.push_back(fmt::format("{}: error: the rig file defines no rig frames", rig_file->string()));
      return errors;
    }
  }
  if (frames.empty()) {
    viewer_scene.notes.push_back("the scene has no rig frames: the device is drawn on top of the base and its "
                           "workspace is not drawn (give a rig file, e.g. scenes/rigs/pomhi.xml)");
  } else {
    // The scene's own rig may be a desktop one (a device frame alone); a rig file is mobile.
    Result<Rig, std::vector<RigError>> rig = rig_file ? Rig::from_frames(frames) : Rig::from_scene(viewer_scene.scene);
    if (!rig.ok()) {
      for (const RigError& e : rig.error()) errors.push_back(e.to_string());
      return errors;
    }
    viewer_scene.rig = std::move(rig).value();
  }
  return viewer_scene;
}

struct StereoViewer::Impl {
  ViewerOptions options;
  std::shared_ptr<StateSource> source;
  osg::ref_ptr<osgViewer::Viewer> viewer;
  std::vector<osg::ref_ptr<osg::Camera>> cameras;
  std::vector<osg::ref_ptr<CaptureCallback>> captures;
  std::unique_ptr<RigGraph> rig_graph;
  // Other rigs (add_rig): each drawn from its own source with the scene's rig frames.
  struct OtherRig {
    std::shared_ptr<StateSource> source;
    std::unique_ptr<RigGraph> graph;
  };
  std::vector<OtherRig> other_rigs;
  std::optional<Rig> rig;
  osg::ref_ptr<osg::Group> scene_root;
  std::unique_ptr<HudOverlay> hud;
  std::function<void(const InputEvent&)> input_handler;
  Pose default_head = Pose::Identity();
  std::optional<RigState> last_state;
  std::vector<EyeView> views;
  std::vector<osg::ref_ptr<osg::MatrixTransform>> object_transforms;
  std::uint64_t frames = 0;

  void place_cameras() {
    if (source) {
      if (std::optional<RigState> s = source->latest()) last_state = std::move(s);
    }
    if (last_state && options.show_rig) rig_graph->update(*last_state);
    for (OtherRig& other : other_rigs) {
      if (std::optional<RigState> s = other.source->latest()) other.graph->update(*s);
    }
    const Pose& head =
        options.view_point == ViewPoint::Head && last_state ? last_state->X_W_head : default_head;
    const ViewGeometry geometry{options.ipd_m, options.fov_deg, options.near_m, options.far_m,
                                options.width, options.height,  options.stereo};
    views = eye_views(head, geometry);
    for (std::size_t i = 0; i < views.size(); ++i) {
      cameras[i]->setViewMatrix(to_osg(Pose(views[i].X_W_camera.inverse()).matrix()));
      cameras[i]->setProjectionMatrix(to_osg(views[i].projection));
    }
  }
};

StereoViewer::StereoViewer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
StereoViewer::~StereoViewer() = default;

Result<std::unique_ptr<StereoViewer>, std::string> StereoViewer::open(const ViewerScene& scene,
                                                                     const ViewerOptions& options,
                                                                     std::shared_ptr<StateSource> source) {
  if (std::string e = options.check(); !e.empty()) return e;
  if (std::string e = check_display(); !e.empty()) return e;
  Result<SceneGraph, std::vector<std::string>> built = build_scene_graph(scene.scene);
  if (!built.ok()) return fmt::format("{}: {}", scene.scene.file.string(), fmt::join(built.error(), "; "));
  SceneGraph& graph = *built;

  auto impl = std::make_unique<Impl>();
  impl->options = options;
  impl->source = std::move(source);
  impl->object_transforms = graph.object_transforms;
  impl->default_head = pick_default_head(graph.objects_bounds_W, options);
  if (options.show_grid) graph.root->addChild(floor_grid(3.0, 1.0, 0.25).get());
  impl->rig = scene.rig;
  impl->scene_root = graph.root;
  impl->rig_graph = std::make_unique<RigGraph>(scene.rig, options.force_scale_m_per_N, options.show_device);
  if (options.show_rig) graph.root->addChild(impl->rig_graph->root());
  if (options.overlay_text) {
    impl->hud = std::make_unique<HudOverlay>(options.eye_width(), options.height);
    graph.root->addChild(impl->hud->root());
  }

  osg::ref_ptr<osg::GraphicsContext::Traits> traits = make_ref<osg::GraphicsContext::Traits>();
  traits->readDISPLAY();
  traits->setUndefinedScreenDetailsToDefaultScreen();
  traits->x = 0;
  traits->y = 0;
  traits->width = options.width;
  traits->height = options.height;
  traits->red = traits->green = traits->blue = traits->alpha = 8;
  traits->depth = 24;
  traits->windowDecoration = !options.offscreen;
  traits->windowName = options.window_title;
  traits->pbuffer = options.offscreen;
  traits->doubleBuffer = !options.offscreen;
  traits->vsync = !options.offscreen;
  // Like check_display(), a connection OSG opens to a busy X server may fail once.
  osg::ref_ptr<osg::GraphicsContext> gc;
  for (int attempt = 0; attempt < 5 && !(gc && gc->valid()); ++attempt) {
    if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    gc = osg::GraphicsContext::createGraphicsContext(traits.get());
  }
  if (!gc || !gc->valid()) {
    return fmt::format("cannot create an OpenGL {} of {}x{} on display '{}' (does the X server offer GLX{}?)",
                       options.offscreen ? "pbuffer" : "window", options.width, options.height, traits->displayName(),
                       options.offscreen ? " 1.3 pbuffers" : "");
  }

  impl->viewer = make_ref<osgViewer::Viewer>();
  osgViewer::Viewer& viewer = *impl->viewer;
  viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
  viewer.setSceneData(graph.root.get());
  osg::Camera* master = viewer.getCamera();
  master->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
  // Eyes at the head would look from inside the head model.
  master->setCullMask(options.view_point == ViewPoint::Head ? ~kHeadNodeMask : ~0u);
  if (options.offscreen) viewer.setKeyEventSetsDone(0);
  // The handler is looked up at each event, so set_input_handler may come after open().
  Impl* impl_ptr = impl.get();
  viewer.addEventHandler(new InputForwarder([impl_ptr](const InputEvent& e) {
    if (impl_ptr->input_handler) impl_ptr->input_handler(e);
  }));

  const GLenum buffer = traits->doubleBuffer ? GL_BACK : GL_FRONT;
  const std::size_t eye_count = options.stereo ? 2 : 1;
  for (std::size_t i = 0; i < eye_count; ++i) {
    auto camera = make_ref<osg::Camera>();
    camera->setGraphicsContext(gc.get());
    const int w = options.eye_width();
    camera->setViewport(new osg::Viewport(static_cast<double>(static_cast<int>(i) * w), 0.0, w, options.height));
    camera->setDrawBuffer(buffer);
    camera->setReadBuffer(buffer);
    camera->setClearColor(osg::Vec4(0.10f, 0.12f, 0.16f, 1.0f));
    camera->setReferenceFrame(osg::Transform::ABSOLUTE_RF);  // the eye matrices are set directly
    auto capture = make_ref<CaptureCallback>();
    camera->setFinalDrawCallback(capture.get());
    viewer.addSlave(camera.get(), true);
    impl->cameras.push_back(camera);
    impl->captures.push_back(capture);
  }
  viewer.realize();
  quiet_mit_shm_errors();
  if (!viewer.isRealized()) {
    return fmt::format("cannot realize the OpenGL {} on display '{}'", options.offscreen ? "pbuffer" : "window",
                       traits->displayName());
  }
  return std::unique_ptr<StereoViewer>(new StereoViewer(std::move(impl)));
}

bool StereoViewer::frame() {
  impl_->place_cameras();
  impl_->viewer->frame();
  ++impl_->frames;
  return !impl_->viewer->done();
}

RgbaImage StereoViewer::frame_and_capture() {
  for (const auto& c : impl_->captures) c->armed = true;
  frame();
  for (const auto& c : impl_->captures) c->armed = false;
  RgbaImage out;
  out.width = impl_->options.width;
  out.height = impl_->options.height;
  out.rgba.assign(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4, 0);
  for (std::size_t i = 0; i < impl_->captures.size(); ++i) {
    const osg::Image& image = *impl_->captures[i]->image;
    const int x0 = impl_->views[i].viewport_x;
    const int w = std::min(image.s(), out.width - x0);
    const int h = std::min(image.t(), out.height);
    for (int row = 0; row < h; ++row) {
      // OpenGL's rows start at the bottom.
      const unsigned char* src = image.data(0, static_cast<unsigned>(row));
      std::uint8_t* dst = out.rgba.data() + (static_cast<std::size_t>(out.height - 1 - row) * static_cast<std::size_t>(out.width) +
                                             static_cast<std::size_t>(x0)) * 4;
      std::memcpy(dst, src, static_cast<std::size_t>(w) * 4);
    }
  }
  for (std::size_t p = 3; p < out.rgba.size(); p += 4) out.rgba[p] = 255;  // opaque PNG
  return out;
}

std::string StereoViewer::run(const std::atomic<bool>& stop) {
  const ViewerOptions& o = impl_->options;
  using Clock = std::chrono::steady_clock;
  const auto period = o.max_frame_rate_Hz > 0.0 ? std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(1.0 / o.max_frame_rate_Hz))
                                                : Clock::duration::zero();
  auto next = Clock::now();
  while (!stop.load(std::memory_order_relaxed)) {
    if (period > Clock::duration::zero()) {
      std::this_thread::sleep_until(next);
      next = std::max(next + period, Clock::now() - period);  // no burst after a stall
    }
    const bool last = o.frames > 0 && impl_->frames + 1 >= static_cast<std::uint64_t>(o.frames);
    if (last && !o.screenshot_png.empty()) return write_png(o.screenshot_png, frame_and_capture());
    if (!frame() || last) break;
  }
  return {};
}

void StereoViewer::set_input_handler(std::function<void(const InputEvent&)> handler) {
  impl_->input_handler = std::move(handler);
}

void StereoViewer::inject(const InputEvent& event) {
  push_input_event(*impl_->viewer->getEventQueue(), event, impl_->options.width, impl_->options.height);
}

void StereoViewer::set_overlay_text(const std::string& text) {
  if (impl_->hud) impl_->hud->set_text(text);
}

void StereoViewer::set_object_pose(std::size_t object, const Pose& X_WO) {
  if (object >= impl_->object_transforms.size() || !impl_->object_transforms[object]) return;
  impl_->object_transforms[object]->setMatrix(to_osg(X_WO));
}

const std::vector<EyeView>& StereoViewer::views() const { return impl_->views; }
std::uint64_t StereoViewer::frames_drawn() const { return impl_->frames; }
const Pose& StereoViewer::default_head() const { return impl_->default_head; }

void StereoViewer::add_rig(std::shared_ptr<StateSource> source) {
  if (!source || !impl_->options.show_rig) return;
  Impl::OtherRig other{std::move(source),
                       std::make_unique<RigGraph>(impl_->rig, impl_->options.force_scale_m_per_N,
                                                  impl_->options.show_device)};
  impl_->scene_root->addChild(other.graph->root());
  impl_->other_rigs.push_back(std::move(other));
}

}  // namespace mhd::viewer
