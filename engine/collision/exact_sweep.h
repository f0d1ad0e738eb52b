#pragma once
// Sweeps of a point against an exact convex primitive (geometry/exact_shape.h), in the
// shape's own frame: the analytic counterpart of segment_triangle.h. The shapes are
// solids: a point inside one may leave it freely, and only a point coming from outside is
// stopped. Because they are convex, the plane tangent to the surface at the point nearest
// any outside point has the whole shape on its far side, so a move that stays on the near
// side of such a plane cannot cross the shape (docs/proxy.md, "Exact primitives").

#include "geometry/exact_shape.h"

#include <Eigen/Core>

#include <optional>

namespace mhd {

/// The point of a shape's surface nearest an outside point, and the outward unit normal
/// there (the normal of the tangent plane that separates the point from the shape).
struct ExactContact {
  Eigen::Vector3d point_O = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal_O = Eigen::Vector3d::Zero();
};

/// The surface point nearest p_O and the outward normal there, for p_O outside the shape
/// or on its surface; nullopt for a point strictly inside. Precondition: p_O finite.
[[nodiscard]] std::optional<ExactContact> exact_nearest_surface(const ExactShape& shape, const Eigen::Vector3d& p_O);

/// Signed distance from p_O to the surface: negative inside. Precondition: p_O finite.
[[nodiscard]] double exact_signed_distance(const ExactShape& shape, const Eigen::Vector3d& p_O);

struct ExactSweep {
  /// Fraction of a -> b the point may travel and still keep at least `skin` from the shape.
  double t_stop = 0.0;
  /// The nearest surface point and its normal, seen from the stop point.
  ExactContact contact;
};

/// Reports a hit when the point moving from a_O to b_O comes within `skin` of the shape
/// while approaching it: entering the shape grown by `skin` (box and cylinder: grown by
/// `skin` along each axis, a little more at edges, so they stop at most 0.75 skin early),
/// or starting within it and moving towards the surface. Every segment that enters the
/// shape from outside is reported. A segment that starts inside the shape, or does not
/// move, is never stopped. Preconditions: skin > 0, inputs finite.
[[nodiscard]] std::optional<ExactSweep> sweep_point_exact(const ExactShape& shape, const Eigen::Vector3d& a_O,
                                                          const Eigen::Vector3d& b_O, double skin);

}  // namespace mhd
