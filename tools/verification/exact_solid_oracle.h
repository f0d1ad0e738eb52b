#pragma once
// The oracle's view of exact primitives (CollisionWorld::set_exact_shape): each a convex
// solid judged by its own signed distance, written here again and sharing no code with
// the engine's analytic sweeps (engine/collision/exact_sweep.cpp), which stop a point by
// intersecting its line with the shape grown by the skin; this side minimises the distance
// along the segment instead. Touching or entering a solid counts as crossing its surface.
// Distances are computed in doubles: exact to rounding, not exact predicates as for
// triangles (a quadric has no exact double-precision predicate to lean on).

#include "geometry/exact_shape.h"
#include "geometry/pose.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace mhd::verify {

class ExactSolids {
 public:
  /// Adds the solid of object `object`, placed by X_WO.
  void add(int object, const ExactShape& shape, const Pose& X_WO);
  [[nodiscard]] bool empty() const { return solids_.empty(); }

  /// Least signed distance from p_W to any solid's surface (negative inside one);
  /// +infinity with none.
  [[nodiscard]] double signed_distance(const Eigen::Vector3d& p_W) const;
  /// True when some point of [a_W, b_W] is on or inside a solid.
  [[nodiscard]] bool touches(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const;
  /// The first solid the segment touches and where (fraction of a -> b), or nullopt.
  struct Touch {
    int object = -1;
    double t = 0.0;
  };
  [[nodiscard]] std::optional<Touch> first_touch(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const;
  /// Every solid the segment touches, with where it first does, in the order added.
  [[nodiscard]] std::vector<Touch> all_touches(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const;
  /// True when the segment comes within clearance_m of a solid whose surface is farther
  /// than 2 clearance_m from a_W (a brush on the way, not the surface the start rests on).
  [[nodiscard]] bool brushes(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W, double clearance_m) const;

 private:
  struct Solid {
    int object = -1;
    ExactShape shape;
    Pose X_OW;
  };
  [[nodiscard]] static double distance_O(const ExactShape& s, const Eigen::Vector3d& p_O);
  // Least distance over the segment, and the fraction where it is reached.
  [[nodiscard]] static std::pair<double, double> segment_minimum(const Solid& s, const Eigen::Vector3d& a_W,
                                                                 const Eigen::Vector3d& b_W);
  std::vector<Solid> solids_;
};

}  // namespace mhd::verify
