#pragma once
// The collision geometry of a scene: shapes (each a MeshBvh in its own frame) placed
// in the world by poses. Moving an object changes its pose only.
// All queries are conservative: they may report a contact a hair early, never miss one.

#include "collision/mesh_bvh.h"
#include "collision/object_tree.h"
#include "collision/sweep_candidates.h"
#include "geometry/exact_shape.h"
#include "geometry/pose.h"
#include "geometry/touchable_faces.h"
#include "geometry/shading_normals.h"

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace mhd {

/// The `triangle` of a TriangleRef that names an object's exact shape, not a triangle.
inline constexpr std::uint32_t kExactSurface = std::numeric_limits<std::uint32_t>::max();

/// One triangle of one object (or, with kExactSurface, the object's exact shape).
struct TriangleRef {
  int object = -1;
  std::uint32_t triangle = 0;
  friend bool operator==(const TriangleRef&, const TriangleRef&) = default;
};

/// First contact of a swept point with the surface.
struct SweepHit {
  TriangleRef where;
  /// Fraction of the segment the point may travel and still keep `skin_m` from the
  /// hit triangle's plane and cross nothing (0 <= t_stop < 1).
  double t_stop = 0.0;
  /// Unit triangle normal in the world, oriented towards the side the segment came from.
  Eigen::Vector3d normal_W = Eigen::Vector3d::Zero();
  /// Plane offset: points x on the triangle satisfy normal_W . x == plane_offset_m.
  double plane_offset_m = 0.0;
};

/// What sweeps cost, and the limit a caller puts on it (the proxy's per-tick budget).
/// A sweep that reaches the limit stops testing triangles and sets `exhausted`; its
/// answer is then incomplete and must not be used.
struct SweepWork {
  int triangle_tests = 0;
  int max_triangle_tests = std::numeric_limits<int>::max();
  bool exhausted = false;
  /// Leaves the sweeps reached, from the tree or the candidate list: tested, or skipped as
  /// ignored. A sweep that reaches its limit stops there, so a triangle-dense spot (a fan
  /// of slivers round one vertex) costs a tick no more than its limit's tests.
  int leaves_reached = 0;
  /// Start a sweep longer than its first piece with a piece of the finest mesh's scale (four
  /// vertex spacings, from 10 µm up to the usual millimetre) instead of a millimetre: for a
  /// caller that ran out of work in a spot denser than its budget, so that its sweeps from
  /// there clear their first pieces (clear_fraction).
  bool fine_pieces = false;
  /// Of a sweep that ran out of work: the fraction of its segment swept clear before it
  /// did, in whole pieces (sweep()); the point may go that far and cross nothing. 0 when
  /// the first piece ran out.
  double clear_fraction = 0.0;
  /// Triangles the latest sweep tested (hit or not), in the order tested: where a caller
  /// may look first for the face beyond an edge the sweep ran along. The first ones, or,
  /// when the sweep tested more than the list holds (a fine mesh), those round the
  /// segment's end before the rest: the face beyond lies under where the sweep ends. A
  /// hint only: nothing here is needed for a sweep's answer.
  static constexpr int kMaxTested = 8;
  std::array<TriangleRef, kMaxTested> tested;
  int tested_count = 0;
  /// Which of `tested` lie round the segment's end (their leaf's box, on a tree's walk).
  std::array<bool, kMaxTested> tested_near_end{};
  /// How many of `tested` are not round the end: none left, a full list has no place for
  /// one that is, and a fine mesh's later tests need not look.
  int tested_far_count = 0;
};

class CollisionWorld {
 public:
  CollisionWorld();
  /// Adds an object; returns its index (0, 1, ...).
  int add_object(std::shared_ptr<const MeshBvh> shape, const Pose& X_WO);

  /// Makes the object an exact primitive (docs/proxy.md, "Exact primitives"): from now on
  /// the sweeps test `shape`, placed by the object's pose, instead of its mesh's triangles
  /// (the mesh stays, for display and for the rigid-body hull), and report its hits as
  /// TriangleRef{object, kExactSurface}. Throws std::out_of_range for an object this world
  /// does not have, std::invalid_argument for a size that is not positive and finite.
  void set_exact_shape(int object, const ExactShape& shape);

  /// Which side of the object's triangles blocks a sweep (both by default): with Front, a
  /// segment that starts behind a triangle passes it. An exact shape is a solid, touched
  /// from outside; this setting is for triangles. Throws std::out_of_range for an object
  /// this world does not have.
  void set_touchable(int object, TouchableFaces faces);
  [[nodiscard]] TouchableFaces touchable(int object) const {
    return objects_.at(static_cast<std::size_t>(object)).touchable;
  }
  /// The object's exact shape, or null where its triangles are swept.
  [[nodiscard]] const ExactShape* exact_shape(int object) const;
  /// For an exact object and a point outside it: the plane tangent to its surface at the
  /// point nearest p_W, as a hit (where = its kExactSurface ref, t_stop 0, normal_W outward,
  /// plane_offset_m through the surface point). The shape lies wholly behind that plane.
  /// nullopt for a point inside, or an object that is not exact.
  [[nodiscard]] std::optional<SweepHit> support_plane(int object, const Eigen::Vector3d& p_W) const;

  /// Moves an object. Never rebuilds its BVH.
  void set_pose(int object, const Pose& X_WO);

  /// Puts every object in the tree over the objects' boxes, by which a sweep visits only
  /// the objects near it. add_object() rebuilds that tree only when the objects added
  /// since would outnumber those in it (so that n adds cost O(n log n)), and the others
  /// are visited one by one meanwhile: a caller that adds many objects calls this after.
  void index_objects();

  [[nodiscard]] int object_count() const { return static_cast<int>(objects_.size()); }
  /// Names this world's shapes: unique to the process, new with every add_object(), kept
  /// by copies (which share the shapes) and by set_pose() (which moves no triangle of a
  /// shape's own frame). A SweepCandidates list gathered here is valid while it is equal.
  [[nodiscard]] std::uint64_t geometry_id() const { return geometry_id_; }
  [[nodiscard]] const Pose& pose(int object) const { return objects_[static_cast<std::size_t>(object)].X_WO; }
  [[nodiscard]] const MeshBvh& shape(int object) const { return *objects_[static_cast<std::size_t>(object)].shape; }
  [[nodiscard]] const std::shared_ptr<const MeshBvh>& shape_ptr(int object) const {
    return objects_[static_cast<std::size_t>(object)].shape;
  }

  /// Sweeps a point from a_W to b_W. Reports the triangle that the point reaches
  /// first, where "reaches" means coming within `skin_m` of the triangle's plane over
  /// the triangle (inflated by a tolerance) while moving towards it. A segment that
  /// crosses any triangle always yields a hit. Triangles in `ignore` are skipped.
  /// With `work`, counts the triangles tested there and stops at its limit (see SweepWork).
  /// With `near`, takes the triangles to test from that list where it holds them, and
  /// gathers it round a short sweep's start where it does not (SweepCandidates): the
  /// answer and the triangles tested are the same as without it. A list gathered in
  /// another world (another geometry_id()) is forgotten first.
  /// Precondition: skin_m > 0, a_W and b_W finite.
  [[nodiscard]] std::optional<SweepHit> sweep(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W,
                                              double skin_m, std::span<const TriangleRef> ignore = {},
                                              SweepWork* work = nullptr, SweepCandidates* near = nullptr) const;

  /// sweep() against `object` alone (the others are not there), with no budget or list.
  /// Throws std::out_of_range for an object this world does not have.
  [[nodiscard]] std::optional<SweepHit> sweep_object(int object, const Eigen::Vector3d& a_W,
                                                     const Eigen::Vector3d& b_W, double skin_m) const;

  /// sweep() against the one triangle `t` (or exact shape; nothing else is tested, the segment is not cut
  /// into pieces): whether, and where, the segment a_W -> b_W meets it.
  [[nodiscard]] std::optional<SweepHit> sweep_triangle(const TriangleRef& t, const Eigen::Vector3d& a_W,
                                                       const Eigen::Vector3d& b_W, double skin_m) const;

  /// Whether the segment a_W -> b_W meets triangle `t` grown by only `inflate_m` on every
  /// edge: sweep_triangle()'s test, in the same frame with the same face normal, with
  /// another growth (its own is a hundredth of the skin), whichever side is touchable.
  /// False for an exact shape's ref, which has no growth to tell apart.
  [[nodiscard]] bool meets_triangle_grown_by(const TriangleRef& t, const Eigen::Vector3d& a_W,
                                             const Eigen::Vector3d& b_W, double skin_m, double inflate_m) const;

  /// Of the triangles `ts`, the one the segment a_W -> b_W meets first for real: the
  /// earliest sweep_triangle() hit (the first listed on a tie) that also meets its triangle
  /// grown by only `graze_inflate_m` (meets_triangle_grown_by()), or nothing. The same
  /// answer as those calls one by one, with the segment taken into each object's frame
  /// once. Adds the triangles tested to `tests`.
  [[nodiscard]] std::optional<SweepHit> first_met(std::span<const TriangleRef> ts, const Eigen::Vector3d& a_W,
                                                  const Eigen::Vector3d& b_W, double skin_m, double graze_inflate_m,
                                                  int& tests) const;

  /// True if p_W's projection onto the triangle's plane lies inside the triangle grown
  /// by margin_m on every edge (the proxy is "over" this triangle). For an exact shape's
  /// ref: true when p_W is outside the shape (a tangent plane lies below it, support_plane()).
  [[nodiscard]] bool projects_onto_triangle(const TriangleRef& t, const Eigen::Vector3d& p_W, double margin_m) const;

  /// Triangle corners in the world frame. Throws std::out_of_range for an exact shape's ref.
  [[nodiscard]] std::array<Eigen::Vector3d, 3> triangle_W(const TriangleRef& t) const;

  /// Gives an object the normals force shading interpolates (set when the scene is
  /// compiled, before any tick reads the world); null takes them away. Throws
  /// std::invalid_argument unless they have one entry per triangle of the object's mesh.
  void set_shading_normals(int object, std::shared_ptr<const ShadingNormals> normals);
  /// The object's shading normals, or null where none were set.
  [[nodiscard]] const ShadingNormals* shading_normals(int object) const {
    return objects_[static_cast<std::size_t>(object)].shading.get();
  }

  /// Unit geometric normal (CCW winding) in the world frame, and the force-shading
  /// normal interpolated at the point closest to p_W (for an exact shape's ref: zero, and
  /// the outward normal at the surface point nearest p_W): from the object's shading normals
  /// (crease-aware, per corner) where it has them, else from the mesh's vertex normals.
  [[nodiscard]] Eigen::Vector3d face_normal_W(const TriangleRef& t) const;
  [[nodiscard]] Eigen::Vector3d shaded_normal_W(const TriangleRef& t, const Eigen::Vector3d& p_W) const;

 private:
  // sweep() over every object (only_object < 0) or over one.
  [[nodiscard]] std::optional<SweepHit> sweep_among(int only_object, const Eigen::Vector3d& a_W,
                                                    const Eigen::Vector3d& b_W, double skin_m,
                                                    std::span<const TriangleRef> ignore, SweepWork* work,
                                                    SweepCandidates* near) const;

  // The earliest hit of a -> b on the exact shapes (all, or only_object's).
  [[nodiscard]] std::optional<SweepHit> sweep_exact(int only_object, const Eigen::Vector3d& a_W,
                                                    const Eigen::Vector3d& b_W, double skin_m,
                                                    std::span<const TriangleRef> ignore, SweepWork* work) const;

  struct Object {
    std::shared_ptr<const MeshBvh> shape;
    std::optional<ExactShape> exact;
    Pose X_WO;
    Pose X_OW;
    std::shared_ptr<const ShadingNormals> shading;
    TouchableFaces touchable = TouchableFaces::Both;
  };
  // A box in the world holding all of the object that a sweep may meet: its triangles,
  // or its exact shape (unbounded for a half-space), a little grown for rounding.
  [[nodiscard]] static Eigen::AlignedBox3d box_W(const Object& o);
  // Calls f(object index) for every object whose box_W comes within reach_m of the
  // segment's box (all, or only_object alone when it is not negative; every object of a
  // world of a few); f returns false to stop.
  template <class F>
  void for_each_object_near(int only_object, const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W, double reach_m,
                            F&& f) const;

  std::vector<Object> objects_;
  std::vector<Eigen::AlignedBox3d> boxes_W_;  // box_W of each object
  ObjectTree object_tree_;                     // over boxes_W_ of objects [0, indexed_)
  std::size_t indexed_ = 0;
  std::size_t exact_count_ = 0;  // objects with an exact shape
  // Up to this many objects, a sweep visits each in turn rather than walk the tree.
  static constexpr std::size_t kObjectsVisitedInTurn = 8;
  std::uint64_t geometry_id_ = 0;
  // The first piece of a long sweep with SweepWork::fine_pieces: a millimetre, or less where
  // a mesh is finer (add_object).
  double fine_first_piece_m_;
};

}  // namespace mhd
