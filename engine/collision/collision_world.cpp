#include "collision/collision_world.h"

#include "collision/exact_sweep.h"
#include "collision/segment_triangle.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace mhd {
namespace {

// Lateral growth of every triangle in the sweep test, relative to the skin. It only has
// to exceed double rounding at scene scale (1e-15 m at metres; this is 10 nm at the
// default skin). It must stay well below the skin: a proxy resting one skin off a face
// at a right-angled convex edge is one skin outside the other face, and a growth of a
// whole skin caught it there as if it touched that face from behind.
constexpr double kInflatePerSkin = 1e-2;
// How near the end of a sweep, in skins, a tested leaf's box must come for the sweep's
// list of tested triangles to keep it first (SweepWork::tested). The face beyond an edge
// lies under the end, a skin and the bend of the faces swept over below it (about a
// micrometre after half a millimetre on a sphere of 0.1 m): room to spare, and still a few
// of a fine mesh's faces.
constexpr double kTestedNearEndPerSkin = 16.0;
// Sweeps longer than this go in pieces (see sweep()). A millimetre: about one triangle of
// a fine scan. The proxy's check straight to a deep HIP starts at the surface it rests on,
// so its first piece finds the hit; at 10 mm that piece's box held a square centimetre of
// the surface (hundreds of triangles on a 200k scan, 527 tests at the bench's p99.9 tick,
// 71 at 1 mm).
constexpr double kFirstPiece_m = 0.001;
// With SweepWork::fine_pieces, on a mesh much finer than that, the first piece is this
// many times its vertex spacing, so that its box holds about as many triangles as a
// millimetre of a fine scan: a millimetre of the 100 M sphere's pole holds over 100,000
// leaves, more than a tick may test, and a sweep from there could never clear a first
// piece. Not under kMinFirstPiece_m. Only on request: more pieces are more walks, and on
// the 10 M sphere they cost its contact ticks a fifth more.
constexpr double kFirstPiecePerSpacing = 4.0;
constexpr double kMinFirstPiece_m = 1e-5;
// A sweep piece no larger than this (a first piece and its margin, or a short move) gathers
// the candidate list when it is not there: the box round the piece's start reaching this
// far each way, so that later first pieces from about the same place fit in it. Larger
// pieces walk the BVH (their boxes would hold too many triangles for a list).
constexpr double kMaxGatheringPiece_m = 2.0 * kFirstPiece_m;
constexpr double kGatherReach_m = 1.25 * kFirstPiece_m;

bool is_ignored(std::span<const TriangleRef> ignore, int object, std::uint32_t triangle) {
  return std::any_of(ignore.begin(), ignore.end(),
                     [&](const TriangleRef& t) { return t.object == object && t.triangle == triangle; });
}

// A triangle's hit as every sweep reports it: its normal in the world frame, and the plane
// through the triangle's first corner.
SweepHit hit_in_world(const Pose& X_WO, const TriangleRef& where, const TriangleSweep& hit,
                      const Eigen::Vector3d& v0_O) {
  SweepHit h;
  h.where = where;
  h.t_stop = hit.t_stop;
  h.normal_W = X_WO.linear() * hit.normal;
  h.plane_offset_m = h.normal_W.dot(X_WO * v0_O);
  return h;
}

// A name for a world's shapes, unique to the process.
std::uint64_t next_geometry_id() {
  static std::atomic<std::uint64_t> last_id{0};
  return ++last_id;
}

// Records a tested triangle in work.tested (see SweepWork::tested): the first ones, then
// those round the sweep's end in place of the others.
void keep_tested(SweepWork& work, const TriangleRef& ref, bool near_end) {
  if (work.tested_count < SweepWork::kMaxTested) {
    const auto i = static_cast<std::size_t>(work.tested_count++);
    work.tested[i] = ref;
    work.tested_near_end[i] = near_end;
    if (!near_end) ++work.tested_far_count;
    return;
  }
  if (!near_end || work.tested_far_count == 0) return;
  // Full: it takes the place of the first one that is not round the end, and the order
  // tested stays.
  int out = 0;
  while (work.tested_near_end[static_cast<std::size_t>(out)]) ++out;
  for (int k = out; k + 1 < SweepWork::kMaxTested; ++k) {
    const auto i = static_cast<std::size_t>(k);
    work.tested[i] = work.tested[i + 1];
    work.tested_near_end[i] = work.tested_near_end[i + 1];
  }
  work.tested.back() = ref;
  work.tested_near_end.back() = true;
  --work.tested_far_count;
}

}  // namespace

CollisionWorld::CollisionWorld() : fine_first_piece_m_(kFirstPiece_m) {}

int CollisionWorld::add_object(std::shared_ptr<const MeshBvh> shape, const Pose& X_WO) {
  const double fine_piece_m = kFirstPiecePerSpacing * shape->vertex_spacing_m();
  if (fine_piece_m < fine_first_piece_m_) fine_first_piece_m_ = std::max(fine_piece_m, kMinFirstPiece_m);
  objects_.push_back(Object{std::move(shape), std::nullopt, X_WO, X_WO.inverse(Eigen::Isometry), nullptr});
  boxes_W_.push_back(box_W(objects_.back()));
  if (objects_.size() > 2 * indexed_) index_objects();
  geometry_id_ = next_geometry_id();
  return static_cast<int>(objects_.size()) - 1;
}

void CollisionWorld::index_objects() {
  if (indexed_ == objects_.size()) return;
  object_tree_.rebuild(boxes_W_);
  indexed_ = objects_.size();
}

Eigen::AlignedBox3d CollisionWorld::box_W(const Object& o) {
  Eigen::AlignedBox3d box_O = o.shape->bounds();
  if (o.exact) {
    const ExactShape& e = *o.exact;
    Eigen::Vector3d half = e.half_extents_m;
    switch (e.kind) {
      case ExactKind::Sphere: half.setConstant(e.radius_m); break;
      case ExactKind::Capsule: half = Eigen::Vector3d(e.radius_m, e.radius_m, e.half_height_m + e.radius_m); break;
      case ExactKind::Cylinder: half = Eigen::Vector3d(e.radius_m, e.radius_m, e.half_height_m); break;
      case ExactKind::Box: break;
      case ExactKind::HalfSpace: {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        return {Eigen::Vector3d::Constant(-kInf), Eigen::Vector3d::Constant(kInf)};
      }
    }
    box_O = Eigen::AlignedBox3d(-half, half);
  }
  Eigen::AlignedBox3d box;
  for (int corner = 0; corner < 8; ++corner) {
    box.extend(o.X_WO * box_O.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
  }
  // Grown by far more than the turn's rounding: a box only ever holds more.
  const double grow_m = 1e-12 * std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff()) + 1e-15;
  return {box.min().array() - grow_m, box.max().array() + grow_m};
}

template <class F>
void CollisionWorld::for_each_object_near(int only_object, const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W,
                                          double reach_m, F&& f) const {
  if (only_object >= 0) {
    (void)f(only_object);
    return;
  }
  // A few objects are visited one by one: their own box tests cost less than a walk.
  if (objects_.size() <= kObjectsVisitedInTurn) {
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      if (!f(static_cast<int>(i))) return;
    }
    return;
  }
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(reach_m);
  const Eigen::AlignedBox3d box(a_W.cwiseMin(b_W) - reach, a_W.cwiseMax(b_W) + reach);
  bool go_on = true;
  object_tree_.for_each_overlapping(box, [&](int object) { return go_on = f(object); });
  for (std::size_t i = indexed_; go_on && i < objects_.size(); ++i) {
    if (ObjectTree::overlaps(boxes_W_[i], box)) go_on = f(static_cast<int>(i));
  }
}

void CollisionWorld::set_exact_shape(int object, const ExactShape& shape) {
  auto& o = objects_.at(static_cast<std::size_t>(object));
  const auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
  bool ok = true;
  switch (shape.kind) {
    case ExactKind::Sphere: ok = positive(shape.radius_m); break;
    case ExactKind::Capsule:
    case ExactKind::Cylinder: ok = positive(shape.radius_m) && positive(shape.half_height_m); break;
    case ExactKind::Box: ok = positive(shape.half_extents_m.minCoeff()) && shape.half_extents_m.allFinite(); break;
    case ExactKind::HalfSpace: break;
  }
  if (!ok) throw std::invalid_argument("CollisionWorld::set_exact_shape: sizes must be positive and finite");
  if (!o.exact) ++exact_count_;
  o.exact = shape;
  boxes_W_[static_cast<std::size_t>(object)] = box_W(o);
  object_tree_.update(object, boxes_W_[static_cast<std::size_t>(object)]);
  // Candidate lists gathered before hold this object's triangles, which are no longer swept.
  geometry_id_ = next_geometry_id();
}

void CollisionWorld::set_touchable(int object, TouchableFaces faces) {
  objects_.at(static_cast<std::size_t>(object)).touchable = faces;
  // Candidate lists hold triangles, not sides: they stay valid.
}

const ExactShape* CollisionWorld::exact_shape(int object) const {
  const auto& o = objects_.at(static_cast<std::size_t>(object));
  return o.exact ? &*o.exact : nullptr;
}

std::optional<SweepHit> CollisionWorld::support_plane(int object, const Eigen::Vector3d& p_W) const {
  const Object& o = objects_.at(static_cast<std::size_t>(object));
  if (!o.exact) return std::nullopt;
  const auto contact = exact_nearest_surface(*o.exact, o.X_OW * p_W);
  if (!contact) return std::nullopt;
  SweepHit h;
  h.where = TriangleRef{object, kExactSurface};
  h.normal_W = o.X_WO.linear() * contact->normal_O;
  h.plane_offset_m = h.normal_W.dot(o.X_WO * contact->point_O);
  return h;
}

std::optional<SweepHit> CollisionWorld::sweep_exact(int only_object, const Eigen::Vector3d& a_W,
                                                    const Eigen::Vector3d& b_W, double skin_m,
                                                    std::span<const TriangleRef> ignore, SweepWork* work) const {
  std::optional<SweepHit> best;
  if (exact_count_ == 0) return best;
  // A hit keeps the point skin_m off the shape: none lies further from the segment.
  for_each_object_near(only_object, a_W, b_W, skin_m + kInflatePerSkin * skin_m, [&](int object) {
    const Object& o = objects_[static_cast<std::size_t>(object)];
    if (!o.exact || is_ignored(ignore, object, kExactSurface)) return true;
    if (work != nullptr) {
      if (work->triangle_tests >= work->max_triangle_tests) {
        work->exhausted = true;
        return false;
      }
      ++work->triangle_tests;  // a primitive costs about what a triangle does
    }
    const auto hit = sweep_point_exact(*o.exact, o.X_OW * a_W, o.X_OW * b_W, skin_m);
    // Ties go to the lower index, whatever order the objects are visited in.
    if (!hit || (best && (hit->t_stop > best->t_stop ||
                          (hit->t_stop == best->t_stop && object > best->where.object)))) {
      return true;
    }
    SweepHit h;
    h.where = TriangleRef{object, kExactSurface};
    h.t_stop = hit->t_stop;
    h.normal_W = o.X_WO.linear() * hit->contact.normal_O;
    h.plane_offset_m = h.normal_W.dot(o.X_WO * hit->contact.point_O);
    best = h;
    return true;
  });
  if (work != nullptr && work->exhausted) return std::nullopt;
  return best;
}

void CollisionWorld::set_pose(int object, const Pose& X_WO) {
  auto& o = objects_.at(static_cast<std::size_t>(object));
  o.X_WO = X_WO;
  o.X_OW = X_WO.inverse(Eigen::Isometry);
  boxes_W_[static_cast<std::size_t>(object)] = box_W(o);
  object_tree_.update(object, boxes_W_[static_cast<std::size_t>(object)]);
  // geometry_id_ is kept: candidate lists hold boxes and triangles in each object's own
  // frame, which a move does not change, so a moving object keeps its list tick to tick.
}

std::optional<SweepHit> CollisionWorld::sweep(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W,
                                              double skin_m, std::span<const TriangleRef> ignore,
                                              SweepWork* work, SweepCandidates* near) const {
  return sweep_among(-1, a_W, b_W, skin_m, ignore, work, near);
}

std::optional<SweepHit> CollisionWorld::sweep_object(int object, const Eigen::Vector3d& a_W,
                                                     const Eigen::Vector3d& b_W, double skin_m) const {
  if (object < 0 || object >= object_count()) throw std::out_of_range("sweep_object: no such object");
  return sweep_among(object, a_W, b_W, skin_m, {}, nullptr, nullptr);
}

std::optional<SweepHit> CollisionWorld::sweep_among(int only_object, const Eigen::Vector3d& a_W,
                                                    const Eigen::Vector3d& b_W, double skin_m,
                                                    std::span<const TriangleRef> ignore, SweepWork* work,
                                                    SweepCandidates* near) const {
  if (near != nullptr) near->bind(geometry_id_);
  if (work != nullptr) {
    work->tested_count = 0;
    work->tested_far_count = 0;
    work->clear_fraction = 0.0;
  }
  // Exact shapes over the whole segment, triangles piece by piece; the earlier hit wins.
  const std::optional<SweepHit> exact = sweep_exact(only_object, a_W, b_W, skin_m, ignore, work);
  if (work != nullptr && work->exhausted) return std::nullopt;
  const auto earliest = [&](std::optional<SweepHit> mesh) {
    if (!exact || (mesh && mesh->t_stop < exact->t_stop)) return mesh;
    return exact;
  };
  // Bit (index mod 64) of every ignored triangle: a triangle whose bit is clear is not in
  // `ignore`, which the test then need not scan (the proxy's list holds up to 16).
  std::uint64_t ignored_bits = 0;
  for (const TriangleRef& t : ignore) ignored_bits |= std::uint64_t{1} << (t.triangle & 63U);
  // One piece of the segment, swept against every object.
  auto sweep_piece = [&](const Eigen::Vector3d& piece_a_W, const Eigen::Vector3d& piece_b_W) -> std::optional<SweepHit> {

  const double inflate_m = kInflatePerSkin * skin_m;
  const double margin_m = skin_m + inflate_m;
  std::optional<SweepHit> best;
  double best_t_stop = std::numeric_limits<double>::infinity();
  double best_t_plane = std::numeric_limits<double>::infinity();

  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(margin_m);
  // Inlined where it is called, as the loop body it was: on the 100 M sphere a call per
  // object and piece cost its contact ticks 6 % (1.72-1.75 against 1.62-1.64 us).
  for_each_object_near(only_object, piece_a_W, piece_b_W, margin_m, [&](int object) __attribute__((always_inline)) {
    const auto oi = static_cast<std::size_t>(object);
    const Object& o = objects_[oi];
    if (o.exact) return true;  // swept above
    if (work != nullptr && work->exhausted) return false;
    const Eigen::Vector3d a_O = o.X_OW * piece_a_W;
    const Eigen::Vector3d b_O = o.X_OW * piece_b_W;
    const Eigen::AlignedBox3d box_O(a_O.cwiseMin(b_O) - margin, a_O.cwiseMax(b_O) + margin);
    if (!box_O.intersects(o.shape->bounds())) return true;

    const MeshBvh& shape = *o.shape;
    const TriangleMesh& mesh = shape.mesh();
    // Tests one triangle; false once the budget is spent, which stops the walk: the answer
    // is thrown away then, and a dense spot would otherwise cost the whole walk.
    auto test = [&](std::uint32_t ti, bool near_end) -> bool {
      if (work != nullptr) ++work->leaves_reached;
      if (((ignored_bits >> (ti & 63U)) & 1U) != 0 && is_ignored(ignore, object, ti)) return true;
      if (work != nullptr) {
        if (work->triangle_tests >= work->max_triangle_tests) {
          work->exhausted = true;
          return false;
        }
        ++work->triangle_tests;
        keep_tested(*work, TriangleRef{object, ti}, near_end);
      }
      const TriangleIndices& t = mesh.triangles[ti];
      const auto hit = sweep_point_triangle(a_O, b_O, mesh.vertices_m[t[0]], mesh.vertices_m[t[1]],
                                            mesh.vertices_m[t[2]], shape.face_normal_O(ti), skin_m, inflate_m);
      // The hit's normal faces the start: the same way as the face's, from the front.
      if (!hit || !touchable_from(o.touchable, hit->normal.dot(shape.face_normal_O(ti)) > 0.0)) return true;
      // Earliest stop wins; ties (shared edges) go to the earlier plane crossing, then
      // to the lower index so results never depend on traversal order.
      const bool better = hit->t_stop < best_t_stop ||
                          (hit->t_stop == best_t_stop &&
                           (hit->t_plane < best_t_plane ||
                            (hit->t_plane == best_t_plane && best &&
                             (object < best->where.object ||
                              (object == best->where.object && ti < best->where.triangle)))));
      if (!better) return true;
      best_t_stop = hit->t_stop;
      best_t_plane = hit->t_plane;
      best = hit_in_world(o.X_WO, TriangleRef{object, ti}, *hit, mesh.vertices_m[t[0]]);
      return true;
    };
    // The same triangles either way: from the list where its box holds the piece's, else
    // from the tree.
    const MeshBvh::QuantizedBox q_O = shape.quantize(box_O);
    const SweepCandidates::Region* region = near != nullptr ? near->find(object, q_O) : nullptr;
    if (region == nullptr && near != nullptr && near->should_gather() && box_O.sizes().maxCoeff() <= kMaxGatheringPiece_m) {
      Eigen::AlignedBox3d gather_O = box_O;
      gather_O.extend(a_O - Eigen::Vector3d::Constant(kGatherReach_m));
      gather_O.extend(a_O + Eigen::Vector3d::Constant(kGatherReach_m));
      region = near->gather(shape, object, shape.quantize(gather_O));
    }
    if (region != nullptr) {
      // At most a list's capacity of leaves: past the budget each returns at once.
      near->for_each_overlapping(*region, q_O, [&](std::uint32_t ti) { (void)test(ti, false); });
    } else {
      if (near != nullptr) near->count_walk();
      // Leaves round the sweep's end, for the list of tested triangles.
      const Eigen::Vector3d end_O = o.X_OW * b_W;
      const Eigen::Vector3d reach = Eigen::Vector3d::Constant(kTestedNearEndPerSkin * skin_m);
      const MeshBvh::QuantizedBox q_end = shape.quantize(Eigen::AlignedBox3d(end_O - reach, end_O + reach));
      shape.for_each_leaf_overlapping(q_O, [&](std::uint32_t ti, const btQuantizedBvhNode& leaf) {
        return test(ti, MeshBvh::overlaps(q_end, leaf));
      });
    }
    return true;
  });
  return best;
  };
  // A long sweep (a deep HIP, the containment ray) would query one box covering much of a
  // large mesh. Sweep it in pieces that double in length from the first piece, nearest
  // first: each box stays small, and the first piece that hits holds the first hit.
  const Eigen::Vector3d ab = b_W - a_W;
  const double length = ab.norm();
  const double first_piece_m = work != nullptr && work->fine_pieces ? fine_first_piece_m_ : kFirstPiece_m;
  if (!(length > first_piece_m)) return earliest(sweep_piece(a_W, b_W));
  double s = 0.0;
  double piece = first_piece_m;
  while (s < length) {
    const double e = std::min(length, s + piece);
    const Eigen::Vector3d p = s == 0.0 ? a_W : Eigen::Vector3d(a_W + (s / length) * ab);
    const Eigen::Vector3d q = e == length ? b_W : Eigen::Vector3d(a_W + (e / length) * ab);
    std::optional<SweepHit> hit = sweep_piece(p, q);
    if (work != nullptr && work->exhausted) {
      // The pieces before this one are clear of triangles, and of the exact shapes short
      // of their first hit.
      work->clear_fraction = exact ? std::min(s / length, exact->t_stop) : s / length;
      return std::nullopt;
    }
    if (hit) {
      hit->t_stop = (s + hit->t_stop * (e - s)) / length;
      return earliest(hit);
    }
    if (exact && exact->t_stop * length <= e) return exact;  // no triangle before it
    s = e;
    piece *= 2.0;
  }
  return exact;
}

std::optional<SweepHit> CollisionWorld::sweep_triangle(const TriangleRef& ref, const Eigen::Vector3d& a_W,
                                                       const Eigen::Vector3d& b_W, double skin_m) const {
  if (ref.triangle == kExactSurface) {
    if (exact_shape(ref.object) == nullptr) return std::nullopt;
    return sweep_exact(ref.object, a_W, b_W, skin_m, {}, nullptr);
  }
  const Object& o = objects_.at(static_cast<std::size_t>(ref.object));
  const TriangleMesh& mesh = o.shape->mesh();
  const TriangleIndices& t = mesh.triangles.at(ref.triangle);
  const auto hit = sweep_point_triangle(o.X_OW * a_W, o.X_OW * b_W, mesh.vertices_m[t[0]], mesh.vertices_m[t[1]],
                                        mesh.vertices_m[t[2]], o.shape->face_normal_O(ref.triangle), skin_m,
                                        kInflatePerSkin * skin_m);
  if (!hit || !touchable_from(o.touchable, hit->normal.dot(o.shape->face_normal_O(ref.triangle)) > 0.0)) {
    return std::nullopt;
  }
  return hit_in_world(o.X_WO, ref, *hit, mesh.vertices_m[t[0]]);
}

bool CollisionWorld::meets_triangle_grown_by(const TriangleRef& ref, const Eigen::Vector3d& a_W,
                                             const Eigen::Vector3d& b_W, double skin_m, double inflate_m) const {
  if (ref.triangle == kExactSurface) return false;
  const Object& o = objects_.at(static_cast<std::size_t>(ref.object));
  const TriangleMesh& mesh = o.shape->mesh();
  const TriangleIndices& t = mesh.triangles.at(ref.triangle);
  return sweep_point_triangle(o.X_OW * a_W, o.X_OW * b_W, mesh.vertices_m[t[0]], mesh.vertices_m[t[1]],
                              mesh.vertices_m[t[2]], o.shape->face_normal_O(ref.triangle), skin_m, inflate_m)
      .has_value();
}

std::optional<SweepHit> CollisionWorld::first_met(std::span<const TriangleRef> ts, const Eigen::Vector3d& a_W,
                                                  const Eigen::Vector3d& b_W, double skin_m, double graze_inflate_m,
                                                  int& tests) const {
  std::optional<SweepHit> first;
  int in_frame = -1;  // the object whose frame a_O and b_O are in
  Eigen::Vector3d a_O = Eigen::Vector3d::Zero();
  Eigen::Vector3d b_O = Eigen::Vector3d::Zero();
  for (const TriangleRef& ref : ts) {
    ++tests;
    if (ref.triangle == kExactSurface) {  // no growth to tell apart: a hit is met for real
      auto hit = sweep_triangle(ref, a_W, b_W, skin_m);
      if (hit && (!first || hit->t_stop < first->t_stop)) first = hit;
      continue;
    }
    const Object& o = objects_.at(static_cast<std::size_t>(ref.object));
    if (ref.object != in_frame) {
      a_O = o.X_OW * a_W;
      b_O = o.X_OW * b_W;
      in_frame = ref.object;
    }
    const TriangleMesh& mesh = o.shape->mesh();
    const TriangleIndices& t = mesh.triangles.at(ref.triangle);
    const Eigen::Vector3d& v0 = mesh.vertices_m[t[0]];
    const Eigen::Vector3d& v1 = mesh.vertices_m[t[1]];
    const Eigen::Vector3d& v2 = mesh.vertices_m[t[2]];
    const Eigen::Vector3d& n_O = o.shape->face_normal_O(ref.triangle);
    const auto hit = sweep_point_triangle(a_O, b_O, v0, v1, v2, n_O, skin_m, kInflatePerSkin * skin_m);
    if (!hit || !touchable_from(o.touchable, hit->normal.dot(n_O) > 0.0)) continue;
    if (first && !(hit->t_stop < first->t_stop)) continue;
    if (!sweep_point_triangle(a_O, b_O, v0, v1, v2, n_O, skin_m, graze_inflate_m)) continue;  // a graze
    first = hit_in_world(o.X_WO, ref, *hit, v0);  // as sweep_triangle() gives it
  }
  return first;
}

std::array<Eigen::Vector3d, 3> CollisionWorld::triangle_W(const TriangleRef& ref) const {
  const Object& o = objects_.at(static_cast<std::size_t>(ref.object));
  const TriangleMesh& mesh = o.shape->mesh();
  const TriangleIndices& t = mesh.triangles.at(ref.triangle);
  return {o.X_WO * mesh.vertices_m[t[0]], o.X_WO * mesh.vertices_m[t[1]], o.X_WO * mesh.vertices_m[t[2]]};
}

bool CollisionWorld::projects_onto_triangle(const TriangleRef& ref, const Eigen::Vector3d& p_W,
                                            double margin_m) const {
  if (ref.triangle == kExactSurface) return support_plane(ref.object, p_W).has_value();
  const auto v = triangle_W(ref);
  const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
  if (!(n.squaredNorm() > 0.0)) return false;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& a = v[static_cast<std::size_t>(i)];
    const Eigen::Vector3d outward = (v[static_cast<std::size_t>((i + 1) % 3)] - a).cross(n);
    const double outside = outward.dot(p_W - a);
    // Within the edge needs no length (margin * length is not negative): most calls ask
    // about a point over the triangle, and the square roots were most of their cost.
    if (margin_m >= 0.0 && !(outside > 0.0)) continue;
    if (outside > margin_m * outward.norm()) return false;
  }
  return true;
}

Eigen::Vector3d CollisionWorld::face_normal_W(const TriangleRef& ref) const {
  if (ref.triangle == kExactSurface) return Eigen::Vector3d::Zero();
  const auto v = triangle_W(ref);
  const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
  const double len = n.norm();
  return len > 0.0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

void CollisionWorld::set_shading_normals(int object, std::shared_ptr<const ShadingNormals> normals) {
  Object& o = objects_.at(static_cast<std::size_t>(object));
  if (normals && normals->corner_normals_O.size() != o.shape->mesh().triangle_count()) {
    throw std::invalid_argument("CollisionWorld::set_shading_normals: one entry per triangle expected");
  }
  o.shading = std::move(normals);
}

Eigen::Vector3d CollisionWorld::shaded_normal_W(const TriangleRef& ref, const Eigen::Vector3d& p_W) const {
  if (ref.triangle == kExactSurface) {
    const auto plane = support_plane(ref.object, p_W);
    return plane ? plane->normal_W : Eigen::Vector3d::Zero();
  }
  const Object& o = objects_.at(static_cast<std::size_t>(ref.object));
  const TriangleMesh& mesh = o.shape->mesh();
  if (o.shading) {
    const Eigen::Vector3d n_O = interpolated_normal_O(mesh, *o.shading, ref.triangle, o.X_OW * p_W);
    return o.X_WO.linear() * n_O;
  }
  const Eigen::Vector3d face = face_normal_W(ref);
  if (mesh.vertex_normals.size() != mesh.vertices_m.size()) return face;
  const TriangleIndices& t = mesh.triangles[ref.triangle];
  const Eigen::Vector3d p = o.X_OW * p_W;
  const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
  const Eigen::Vector3d& b = mesh.vertices_m[t[1]];
  const Eigen::Vector3d& c = mesh.vertices_m[t[2]];
  // Barycentric weights of p's projection, clamped into the triangle.
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double denom = n.squaredNorm();
  if (!(denom > 0.0)) return face;
  double wa = n.dot((b - p).cross(c - p)) / denom;
  double wb = n.dot((c - p).cross(a - p)) / denom;
  double wc = 1.0 - wa - wb;
  wa = std::max(wa, 0.0);
  wb = std::max(wb, 0.0);
  wc = std::max(wc, 0.0);
  const double sum = wa + wb + wc;
  if (!(sum > 0.0)) return face;
  const Eigen::Vector3d blended_O = (wa * mesh.vertex_normals[t[0]].cast<double>() +
                                     wb * mesh.vertex_normals[t[1]].cast<double>() +
                                     wc * mesh.vertex_normals[t[2]].cast<double>()) /
                                    sum;
  const double len = blended_O.norm();
  if (!(len > 0.0)) return face;
  return o.X_WO.linear() * (blended_O / len);
}

}  // namespace mhd
