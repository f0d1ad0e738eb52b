#pragma once
// An exact, independent checker for "a moving point never crosses a surface". It shares
// no code with the collision layer: it copies the triangles into the world frame and
// answers with CGAL's exact predicates (Epick) over its own AABB tree, so a bug in the
// engine's conservative sweeps cannot hide itself here. Touching counts as crossing; on
// an object touchable from one side, only a move that meets a triangle from that side
// does (geometry/touchable_faces.h), decided by the exact orientation of its start.
// Objects that the world sweeps as exact primitives are judged as the solids they are
// (exact_solid_oracle.h), not by their tessellations: touching or entering one crosses it,
// and a hit on one is reported as TriangleRef{object, kExactSurface}.

#include "collision/collision_world.h"
#include "geometry/pose.h"
#include "geometry/touchable_faces.h"
#include "geometry/triangle_mesh.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace mhd::verify {

/// A mesh placed in the world, as the oracle reads it during construction.
struct PlacedMesh {
  const TriangleMesh* mesh = nullptr;  ///< not owned; read only in the constructor
  Pose X_WO = Pose::Identity();
  /// A move that meets a triangle from a side that is not touchable does not touch it.
  TouchableFaces touchable = TouchableFaces::Both;
};

/// A triangle a segment touches.
struct OracleHit {
  TriangleRef where;
  /// Fraction of a->b at the first touching point, in [0, 1]. Whether the segment
  /// touches is exact; this position is computed in doubles.
  double t = 0.0;
};

enum class SurfaceSide { Outside, OnSurface, Inside };

class SurfaceCrossingOracle {
 public:
  /// Snapshot of the world at its current poses; later set_pose() calls are not seen.
  explicit SurfaceCrossingOracle(const CollisionWorld& world);
  /// Object i of the oracle is meshes[i]; triangles with invalid indices are skipped.
  explicit SurfaceCrossingOracle(std::span<const PlacedMesh> meshes);
  explicit SurfaceCrossingOracle(const TriangleMesh& mesh, const Pose& X_WO = Pose::Identity());

  ~SurfaceCrossingOracle();
  SurfaceCrossingOracle(SurfaceCrossingOracle&&) noexcept;
  SurfaceCrossingOracle& operator=(SurfaceCrossingOracle&&) noexcept;
  SurfaceCrossingOracle(const SurfaceCrossingOracle&) = delete;
  SurfaceCrossingOracle& operator=(const SurfaceCrossingOracle&) = delete;

  /// Exact: true iff the closed segment [a_W, b_W] shares at least one point with any
  /// triangle (interior, edge or vertex; coplanar overlap included). a_W == b_W tests
  /// the point. Degenerate (zero-area) triangles count as the segment or point they are.
  [[nodiscard]] bool segment_touches_surface(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const;
  [[nodiscard]] bool point_touches_surface(const Eigen::Vector3d& p_W) const;

  /// Exact: true iff the segment [a_W, b_W] touches a triangle (of non-zero area) whose
  /// front a_W lies strictly in front of, whichever side its object is touchable from:
  /// from a hand at a_W, a proxy at b_W is behind that face.
  [[nodiscard]] bool segment_meets_a_front(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const;

  /// True when the segment [a_W, b_W] comes within clearance_m of a triangle (or
  /// degenerate edge) that lies farther than 2 clearance_m from a_W: a brush of the
  /// surface on the way, not the surface the start rests on. Distances are constructed in
  /// doubles (for clearances, not for deciding contact).
  [[nodiscard]] bool segment_brushes_surface(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W,
                                             double clearance_m) const;

  /// Every touched triangle, ordered by t (then by object, triangle).
  [[nodiscard]] std::vector<OracleHit> touched_triangles(const Eigen::Vector3d& a_W,
                                                         const Eigen::Vector3d& b_W) const;
  /// The touched triangle with the smallest t; nullopt iff segment_touches_surface is false.
  [[nodiscard]] std::optional<OracleHit> first_touched_triangle(const Eigen::Vector3d& a_W,
                                                                const Eigen::Vector3d& b_W) const;

  /// Where p lies with respect to the closed objects (see is_closed), by exact ray
  /// parity: Inside if inside any closed object, OnSurface if on one's surface.
  /// A closed mesh wound inside out (its volume negative) is a room seen from within, as
  /// the engine reads it: its solid lies beyond its walls, where parity is even.
  /// Open objects are ignored.
  [[nodiscard]] SurfaceSide side_of_closed_surfaces(const Eigen::Vector3d& p_W) const;
  /// side_of_closed_surfaces(p) != Outside.
  [[nodiscard]] bool point_inside_closed_mesh(const Eigen::Vector3d& p_W) const;

  /// Distance from p to the nearest triangle (constructions in doubles; for clearances,
  /// not for deciding contact). +infinity for an empty oracle. Builds a search
  /// structure on first use (thread-safe).
  [[nodiscard]] double distance_to_surface(const Eigen::Vector3d& p_W) const;

  /// An exact primitive is closed. Another object is closed when, after welding vertices with identical coordinates, every
  /// edge of its non-degenerate triangles is shared by an even number of them (so ray
  /// parity defines an inside). Not closed: open scans, planes, meshes with cracks.
  [[nodiscard]] bool is_closed(int object) const;
  [[nodiscard]] int object_count() const;

  /// The triangles as the oracle holds them (world frame), in a fixed order. An exact
  /// primitive's tessellation is among them (stroke sets aim at it) though its solid,
  /// not they, decides contact.
  [[nodiscard]] std::size_t triangle_count() const;
  [[nodiscard]] const std::array<Eigen::Vector3d, 3>& triangle_W(std::size_t i) const;
  [[nodiscard]] const TriangleRef& triangle_ref(std::size_t i) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mhd::verify
