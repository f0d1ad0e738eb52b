#pragma once
// Internal to mhd_viewer (includes OSG): the rig drawn from a RigState. The HIP and the
// proxy are small spheres (the proxy turns red in contact), the force an arrow from the
// proxy, the base a short cylinder with a nose towards its x, the arm a rod from the
// device origin to the HIP, the user's head a sphere with a nose along its gaze, and the
// arm's usable workspace a translucent box (only with rig frames, which place it).

#include "kinematics/rig.h"
#include "viewer/rig_state.h"

#include <osg/Group>
#include <osg/MatrixTransform>
#include <osg/ShapeDrawable>
#include <osg/Switch>
#include <osg/ref_ptr>

#include <optional>

namespace mhd::viewer {

/// Node mask bit of the head model; eye cameras at the head leave it out.
inline constexpr unsigned kHeadNodeMask = 0x2;

class RigGraph {
 public:
  /// `rig` places the device and its workspace; without it the arm starts on top of the base.
  /// Without `show_device` only the HIP, the proxy and the force are drawn.
  RigGraph(std::optional<Rig> rig, double force_scale_m_per_N, bool show_device = true);

  [[nodiscard]] osg::Node* root() const { return root_.get(); }
  /// Moves every part to the state; the first call makes the rig visible.
  void update(const RigState& state);

 private:
  osg::ref_ptr<osg::MatrixTransform> part(osg::Shape* shape, const osg::Vec4& colour, unsigned mask = ~0u);

  std::optional<Rig> rig_;
  double force_scale_m_per_N_;
  bool show_device_;
  osg::ref_ptr<osg::Switch> root_;
  osg::ref_ptr<osg::MatrixTransform> hip_, proxy_, force_shaft_, force_head_, base_, arm_, column_, head_, workspace_;
  osg::ref_ptr<osg::ShapeDrawable> proxy_drawable_;
};

}  // namespace mhd::viewer
