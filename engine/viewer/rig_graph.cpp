#include "viewer/rig_graph.h"

#include "viewer/osg_convert.h"

#include <osg/BlendFunc>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/Shape>

#include <cmath>

namespace mhd::viewer {
namespace {

constexpr double kPointRadius_m = 0.012;
constexpr double kBaseRadius_m = 0.30;
constexpr double kBaseHeight_m = 0.35;
constexpr double kHeadRadius_m = 0.10;

/// Maps the unit z segment [0, 1] (of a shape along z) onto a -> b with radius r.
osg::Matrixd along(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r) {
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  const Eigen::Quaterniond q =
      length > 1e-12 ? Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), d / length) : Eigen::Quaterniond::Identity();
  Eigen::Affine3d X = Eigen::Affine3d::Identity();
  X.translate(a);
  X.rotate(q);
  X.scale(Eigen::Vector3d(r, r, std::max(length, 1e-9)));
  return to_osg(X.matrix());
}

Pose base_pose_W(const BasePose& base) {
  Pose X = Pose::Identity();
  X.linear() = Eigen::AngleAxisd(base.heading_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  X.translation() = Eigen::Vector3d(base.x_m, 0.0, base.z_m);
  return X;
}

}  // namespace

osg::ref_ptr<osg::MatrixTransform> RigGraph::part(osg::Shape* shape, const osg::Vec4& colour, unsigned mask) {
  auto drawable = make_ref<osg::ShapeDrawable>(shape);
  drawable->setColor(colour);
  auto transform = make_ref<osg::MatrixTransform>();
  transform->addChild(drawable.get());
  transform->setNodeMask(mask);
  root_->addChild(transform.get(), true);
  return transform;
}

RigGraph::RigGraph(std::optional<Rig> rig, double force_scale_m_per_N, bool show_device)
    : rig_(std::move(rig)),
      force_scale_m_per_N_(force_scale_m_per_N),
      show_device_(show_device),
      root_(make_ref<osg::Switch>()) {
  root_->setName("rig");
  root_->getOrCreateStateSet()->setMode(GL_NORMALIZE, osg::StateAttribute::ON);
  const auto r = static_cast<float>(kPointRadius_m);
  hip_ = part(new osg::Sphere(osg::Vec3(), r), osg::Vec4(1.0f, 0.85f, 0.1f, 1.0f));
  proxy_ = part(new osg::Sphere(osg::Vec3(), r), osg::Vec4(0.2f, 0.9f, 0.3f, 1.0f));
  proxy_drawable_ = dynamic_cast<osg::ShapeDrawable*>(proxy_->getChild(0));
  // Unit shapes along z from 0 to 1, scaled by along().
  force_shaft_ = part(new osg::Cylinder(osg::Vec3(0.0f, 0.0f, 0.5f), 1.0f, 1.0f), osg::Vec4(0.95f, 0.2f, 0.2f, 1.0f));
  force_head_ = part(new osg::Cone(osg::Vec3(0.0f, 0.0f, 0.25f), 1.0f, 1.0f), osg::Vec4(0.95f, 0.2f, 0.2f, 1.0f));
  base_ = part(new osg::Cylinder(osg::Vec3(0.0f, 0.0f, 0.5f), 1.0f, 1.0f), osg::Vec4(0.3f, 0.3f, 0.35f, 1.0f));
  column_ = part(new osg::Cylinder(osg::Vec3(0.0f, 0.0f, 0.5f), 1.0f, 1.0f), osg::Vec4(0.5f, 0.5f, 0.55f, 1.0f));
  arm_ = part(new osg::Cylinder(osg::Vec3(0.0f, 0.0f, 0.5f), 1.0f, 1.0f), osg::Vec4(0.75f, 0.75f, 0.8f, 1.0f));
  head_ = part(new osg::Sphere(osg::Vec3(), static_cast<float>(kHeadRadius_m)), osg::Vec4(0.9f, 0.75f, 0.6f, 1.0f),
               kHeadNodeMask);
  // The head's nose: a cone along the head's x (its gaze).
  auto nose_turn = make_ref<osg::MatrixTransform>(osg::Matrixd::rotate(osg::Vec3(0, 0, 1), osg::Vec3(1, 0, 0)));
  auto nose_shape = make_ref<osg::ShapeDrawable>(new osg::Cone(osg::Vec3(0.0f, 0.0f, 0.11f), 0.03f, 0.08f));
  nose_shape->setColor(osg::Vec4(0.9f, 0.6f, 0.5f, 1.0f));
  nose_turn->addChild(nose_shape.get());
  head_->addChild(nose_turn.get());

  if (rig_) {
    const WorkspaceBox box = rig_->device().usable_workspace();
    const Eigen::Vector3d size = box.max_P_m - box.min_P_m;
    workspace_ = part(new osg::Box(to_osg(box.center_P_m()), static_cast<float>(size.x()), static_cast<float>(size.y()),
                                   static_cast<float>(size.z())),
                      osg::Vec4(0.3f, 0.6f, 1.0f, 0.18f));
    osg::StateSet* s = workspace_->getOrCreateStateSet();
    s->setMode(GL_BLEND, osg::StateAttribute::ON);
    s->setAttributeAndModes(make_ref<osg::BlendFunc>(static_cast<GLenum>(GL_SRC_ALPHA), static_cast<GLenum>(GL_ONE_MINUS_SRC_ALPHA)).get());
    s->setAttributeAndModes(make_ref<osg::Depth>(osg::Depth::LESS, 0.0, 1.0, false).get());
    s->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
  }
  root_->setAllChildrenOff();
}

void RigGraph::update(const RigState& s) {
  root_->setAllChildrenOn();
  hip_->setMatrix(osg::Matrixd::translate(to_osg(s.p_W_hip_m)));
  proxy_->setMatrix(osg::Matrixd::translate(to_osg(s.p_W_proxy_m)));
  if (proxy_drawable_) {
    proxy_drawable_->setColor(s.in_contact ? osg::Vec4(0.95f, 0.15f, 0.15f, 1.0f) : osg::Vec4(0.2f, 0.9f, 0.3f, 1.0f));
  }

  const double force_N = s.force_W_N.norm();
  const double length_m = force_N * force_scale_m_per_N_;
  const bool show_force = length_m > 1e-4;
  root_->setChildValue(force_shaft_.get(), show_force);
  root_->setChildValue(force_head_.get(), show_force);
  if (show_force) {
    const Eigen::Vector3d dir = s.force_W_N / force_N;
    const double head_m = std::min(0.3 * length_m, 0.03);
    const Eigen::Vector3d tip = s.p_W_proxy_m + length_m * dir;
    const Eigen::Vector3d neck = tip - head_m * dir;
    force_shaft_->setMatrix(along(s.p_W_proxy_m, neck, 0.006));
    force_head_->setMatrix(along(neck, tip, 0.015));
  }

  const Pose X_W_base = base_pose_W(s.base);
  base_->setMatrix(along(X_W_base.translation(), X_W_base * Eigen::Vector3d(0.0, kBaseHeight_m, 0.0), kBaseRadius_m));
  Eigen::Vector3d p_W_arm_root = X_W_base * Eigen::Vector3d(0.0, kBaseHeight_m, 0.0);
  if (rig_) {
    const Pose X_W_phantom = rig_->X_W_phantom(rig_->X_W_robot_from_base(s.base));
    p_W_arm_root = X_W_phantom.translation();
    workspace_->setMatrix(to_osg(X_W_phantom));
  }
  column_->setMatrix(along(X_W_base * Eigen::Vector3d(0.0, kBaseHeight_m, 0.0), p_W_arm_root, 0.03));
  arm_->setMatrix(along(p_W_arm_root, s.p_W_hip_m, 0.008));
  head_->setMatrix(to_osg(s.X_W_head));
  if (!show_device_) {
    for (osg::Node* n : {base_.get(), column_.get(), arm_.get(), head_.get(), workspace_.get()}) {
      if (n != nullptr) root_->setChildValue(n, false);
    }
  }
}

}  // namespace mhd::viewer
