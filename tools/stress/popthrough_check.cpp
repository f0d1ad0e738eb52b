#include "stress/popthrough_check.h"

#include "collision/point_containment.h"

#include <algorithm>
#include <memory>

namespace mhd::stress {

PopThroughChecker::PopThroughChecker(const CollisionWorld& world, const verify::SurfaceCrossingOracle& oracle,
                                     EngineContainment engine, int engine_stride,
                                     const verify::FollowTolerance& follow)
    : world_(world), oracle_(oracle), engine_(engine), follow_(follow), engine_stride_(std::max(engine_stride, 1)) {
  for (int i = 0; i < world.object_count(); ++i) {
    const std::shared_ptr<const MeshBvh> shape(std::shared_ptr<const MeshBvh>{}, &world.shape(i));
    if (!oracle.is_closed(i)) continue;
    const int id = closed_world_.add_object(shape, world.pose(i));
    if (const ExactShape* exact = world.exact_shape(i)) closed_world_.set_exact_shape(id, *exact);
  }
}

void PopThroughChecker::check_leg(int leg, const Eigen::Vector3d& a, const Eigen::Vector3d& b, TickVerdict& v) const {
  if (v.crossed || !oracle_.segment_touches_surface(a, b)) return;
  v.crossed = true;
  v.leg = leg;
  v.leg_from_W = a;
  v.leg_to_W = b;
  v.hit = oracle_.first_touched_triangle(a, b);
}

void PopThroughChecker::check_end(const Eigen::Vector3d& p, bool ask_engine, TickVerdict& v) {
  v.inside = oracle_.point_inside_closed_mesh(p);
  if (v.inside) v.penetration_m = oracle_.distance_to_surface(p);
  if (ask_engine) {
    v.engine_checked = true;
    v.inside_engine = closed_world_.object_count() > 0 && point_inside_surface(closed_world_, p);
  }
  previous_inside_ = v.inside;
  previous_engine_checked_ = v.engine_checked;
  previous_inside_engine_ = v.inside_engine;
  previous_depth_m_ = v.penetration_m;
}

TickVerdict PopThroughChecker::check_reset(const Eigen::Vector3d& p_W) {
  TickVerdict v;
  previous_ = p_W;
  started_ = true;
  check_leg(-1, p_W, p_W, v);
  check_end(p_W, engine_ != EngineContainment::Off, v);
  return v;
}

TickVerdict PopThroughChecker::check_tick(const Eigen::Vector3d& p_W_hip, std::span<const Eigen::Vector3d> path_W,
                                          const Eigen::Vector3d& proxy_W, const Eigen::Vector3d& force_W,
                                          bool in_contact) {
  TickVerdict v;
  if (!started_) (void)check_reset(path_W.empty() ? proxy_W : path_W.front());
  const verify::FollowVerdict follow = verify::check_follow(oracle_, previous_, p_W_hip, proxy_W, force_W, follow_);
  v.follow_failed = follow.failed();
  v.follow_kind = follow.kind;
  v.follow_brushed = follow.brushed;
  v.follow_gap_m = follow.gap_m;
  v.hip_in_free_view = follow.hip_in_free_view;
  v.force_N = follow.force_N;
  Eigen::Vector3d at = previous_;
  const int n = static_cast<int>(path_W.size());
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& next = path_W[static_cast<std::size_t>(i)];
    if (next != at) check_leg(i - 1, at, next, v);
    at = next;
  }
  if (proxy_W != at) check_leg(n - 1, at, proxy_W, v);

  if (proxy_W == previous_) {
    // Same point as last tick: same answer.
    v.inside = previous_inside_;
    v.engine_checked = previous_engine_checked_;
    v.inside_engine = previous_inside_engine_;
    v.penetration_m = previous_depth_m_;
  } else {
    bool ask_engine = engine_ == EngineContainment::Every || (engine_ == EngineContainment::Contact && in_contact);
    if (ask_engine) {
      ask_engine = engine_countdown_ == 0;
      engine_countdown_ = ask_engine ? engine_stride_ - 1 : engine_countdown_ - 1;
    }
    check_end(proxy_W, ask_engine, v);
  }
  if (v.crossed && !v.inside && v.hit && v.hit->where.triangle != kExactSurface) {
    // Depth behind the plane of the crossed triangle, seen from where the leg came from.
    const auto t = world_.triangle_W(v.hit->where);
    Eigen::Vector3d normal = (t[1] - t[0]).cross(t[2] - t[0]);
    if (normal.squaredNorm() > 0.0) {
      normal.normalize();
      if (normal.dot(v.leg_from_W - t[0]) < 0.0) normal = -normal;
      v.penetration_m = std::max(0.0, -normal.dot(proxy_W - t[0]));
    }
  }
  previous_ = proxy_W;
  return v;
}

}  // namespace mhd::stress
