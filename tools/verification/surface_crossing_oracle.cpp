#include "verification/surface_crossing_oracle.h"

#include "verification/exact_solid_oracle.h"

// CGAL stays in this one translation unit (it is slow to compile).
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>

namespace mhd::verify {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Segment = K::Segment_3;
using Triangle = K::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using SegmentIterator = std::vector<Segment>::const_iterator;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, TriangleIterator>>>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, SegmentIterator>>>;

Point to_point(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d to_eigen(const Point& p) { return {p.x(), p.y(), p.z()}; }

// Fraction of a->b at x (x is on or near the segment), clamped to [0, 1].
double param_on(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Point& x) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return 0.0;
  return std::clamp((to_eigen(x) - a).dot(ab) / len2, 0.0, 1.0);
}

// Smallest fraction of a->b inside an intersection result (a point or a segment).
template <class Result>
double first_param(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Result& result, double fallback) {
  if (!result) return fallback;
  if (const Point* p = boost::get<Point>(&*result)) return param_on(a, b, *p);
  if (const Segment* s = boost::get<Segment>(&*result)) {
    return std::min(param_on(a, b, s->source()), param_on(a, b, s->target()));
  }
  return fallback;
}

// Bit pattern of a vertex for exact welding; -0.0 and 0.0 weld.
using VertexKey = std::array<std::uint64_t, 3>;
VertexKey key_of(const Eigen::Vector3d& v) {
  return {std::bit_cast<std::uint64_t>(v.x() + 0.0), std::bit_cast<std::uint64_t>(v.y() + 0.0),
          std::bit_cast<std::uint64_t>(v.z() + 0.0)};
}

bool triangle_indices_valid(const TriangleIndices& t, std::size_t vertex_count) {
  return t[0] < vertex_count && t[1] < vertex_count && t[2] < vertex_count;
}

// The volume a closed mesh's windings enclose, negative where it is wound inside out.
double signed_volume_m3(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const TriangleIndices& t : mesh.triangles) {
    if (!triangle_indices_valid(t, mesh.vertices_m.size())) continue;
    six_volume += mesh.vertices_m[t[0]].dot(mesh.vertices_m[t[1]].cross(mesh.vertices_m[t[2]]));
  }
  return six_volume / 6.0;
}

// Even edge incidence after exact welding (a mod-2 cycle: ray parity is well defined).
// Sorted arrays, not hash maps: at tens of millions of triangles a map's nodes would take
// more memory than the oracle itself, and a freed array goes back to the system.
bool mesh_is_closed(const TriangleMesh& mesh) {
  const std::size_t n = mesh.vertices_m.size();
  // Weld: vertices with identical coordinates share the id of the first in sorted order.
  std::vector<std::uint32_t> canonical(n);
  {
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return key_of(mesh.vertices_m[a]) < key_of(mesh.vertices_m[b]);
    });
    for (std::size_t k = 0; k < n; ++k) {
      const bool same = k > 0 && key_of(mesh.vertices_m[order[k]]) == key_of(mesh.vertices_m[order[k - 1]]);
      canonical[order[k]] = same ? canonical[order[k - 1]] : order[k];
    }
  }
  std::vector<std::uint64_t> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (const TriangleIndices& t : mesh.triangles) {
    if (!triangle_indices_valid(t, n)) continue;
    const std::array<std::uint32_t, 3> c{canonical[t[0]], canonical[t[1]], canonical[t[2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) continue;
    for (std::size_t e = 0; e < 3; ++e) {
      const std::uint32_t u = c[e];
      const std::uint32_t v = c[(e + 1) % 3];
      edges.push_back((std::uint64_t{std::min(u, v)} << 32) | std::max(u, v));
    }
  }
  if (edges.empty()) return false;
  std::sort(edges.begin(), edges.end());
  for (std::size_t k = 0; k < edges.size();) {
    std::size_t run = k + 1;
    while (run < edges.size() && edges[run] == edges[k]) ++run;
    if ((run - k) % 2 != 0) return false;
    k = run;
  }
  return true;
}

}  // namespace

/// One distance hint per this many triangles (distance_to_surface).
constexpr std::size_t kDistanceHintStride = 16;

struct SurfaceCrossingOracle::Impl {
  // Every triangle, world frame, in input order (degenerate ones included).
  std::vector<std::array<Eigen::Vector3d, 3>> triangles_W;
  std::vector<TriangleRef> refs;
  std::vector<bool> closed;  // per object
  // Per object: closed and wound inside out (a negative volume), so a room seen from
  // within: its inside by parity is the room's air, and the solid lies beyond its walls.
  std::vector<bool> room;
  std::vector<TouchableFaces> touchable;  // per object
  bool one_sided = false;  // some object is touchable from one side only

  // Non-degenerate triangles go in a triangle tree; collinear ones become their
  // non-degenerate edges in a segment tree; single points are checked one by one.
  std::vector<Triangle> cgal_triangles;
  std::vector<std::size_t> cgal_triangle_source;
  std::vector<Segment> cgal_segments;
  std::vector<std::size_t> cgal_segment_source;
  std::vector<Point> cgal_points;
  std::vector<std::size_t> cgal_point_source;
  TriangleTree triangle_tree;
  SegmentTree segment_tree;
  Eigen::AlignedBox3d bounds_W;

  std::once_flag distance_once;
  ExactSolids exact;  // the exact primitives, judged as solids
  std::vector<bool> is_exact;  // per object: its triangles are listed, not judged

  void add_triangle(const std::array<Eigen::Vector3d, 3>& abc, const TriangleRef& ref) {
    const std::size_t source = triangles_W.size();
    triangles_W.push_back(abc);
    refs.push_back(ref);
    for (const Eigen::Vector3d& v : abc) bounds_W.extend(v);
    if (static_cast<std::size_t>(ref.object) < is_exact.size() && is_exact[static_cast<std::size_t>(ref.object)]) return;
    const Point a = to_point(abc[0]), b = to_point(abc[1]), c = to_point(abc[2]);
    if (!CGAL::collinear(a, b, c)) {
      cgal_triangles.emplace_back(a, b, c);
      cgal_triangle_source.push_back(source);
    } else if (touchable[static_cast<std::size_t>(ref.object)] != TouchableFaces::Both) {
      // A one-sided surface has no side where it has no area: nothing to touch.
    } else if (a == b && b == c) {
      cgal_points.push_back(a);
      cgal_point_source.push_back(source);
    } else {
      for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        if (p == q) continue;
        cgal_segments.emplace_back(p, q);
        cgal_segment_source.push_back(source);
      }
    }
  }

  void build(std::span<const PlacedMesh> meshes) {
    bounds_W.setEmpty();
    closed.reserve(meshes.size());
    std::size_t total = 0;
    for (const PlacedMesh& placed : meshes) {
      touchable.push_back(placed.touchable);
      one_sided = one_sided || placed.touchable != TouchableFaces::Both;
      total += placed.mesh->triangles.size();
    }
    // Reserved, not grown: a doubling vector of tens of millions of triangles holds up to
    // twice what it needs, and three times while it moves.
    triangles_W.reserve(total);
    refs.reserve(total);
    cgal_triangles.reserve(total);
    cgal_triangle_source.reserve(total);
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      const TriangleMesh& mesh = *meshes[i].mesh;
      const Pose& X_WO = meshes[i].X_WO;
      const bool primitive = i < is_exact.size() && is_exact[i];
      closed.push_back(primitive || mesh_is_closed(mesh));
      room.push_back(!primitive && closed.back() && signed_volume_m3(mesh) < 0.0);
      const std::size_t n = mesh.vertices_m.size();
      for (std::size_t j = 0; j < mesh.triangles.size(); ++j) {
        const TriangleIndices& t = mesh.triangles[j];
        if (!triangle_indices_valid(t, n)) continue;
        add_triangle({X_WO * mesh.vertices_m[t[0]], X_WO * mesh.vertices_m[t[1]], X_WO * mesh.vertices_m[t[2]]},
                     TriangleRef{static_cast<int>(i), static_cast<std::uint32_t>(j)});
      }
    }
    triangle_tree.insert(cgal_triangles.cbegin(), cgal_triangles.cend());
    triangle_tree.build();
    segment_tree.insert(cgal_segments.cbegin(), cgal_segments.cend());
    segment_tree.build();
  }

  // Whether segment a->b, which touches cgal_triangles[k], meets a side of it that is
  // there: it comes from the front when a is on the side the counter-clockwise normal
  // points to (CGAL's positive side of the plane through the corners in order), or starts
  // on the plane and goes behind it. A move within the plane touches either side.
  [[nodiscard]] bool side_is_there(std::size_t k, const Point& a, const Point& b) const {
    const TouchableFaces faces = touchable[static_cast<std::size_t>(refs[cgal_triangle_source[k]].object)];
    if (faces == TouchableFaces::Both) return true;
    const Triangle& t = cgal_triangles[k];
    const CGAL::Orientation at_a = CGAL::orientation(t[0], t[1], t[2], a);
    if (at_a != CGAL::COPLANAR) return touchable_from(faces, at_a == CGAL::POSITIVE);
    const CGAL::Orientation at_b = CGAL::orientation(t[0], t[1], t[2], b);
    return at_b == CGAL::COPLANAR || touchable_from(faces, at_b == CGAL::NEGATIVE);
  }

  // Calls f(source index, t) for every touched primitive. Query: Point or Segment.
  template <class Query, class F>
  void for_each_touch(const Query& query, const Eigen::Vector3d& a, const Eigen::Vector3d& b, F&& f) const {
    constexpr bool kIsPoint = std::is_same_v<Query, Point>;
    if (!triangle_tree.empty()) {
      std::vector<TriangleIterator> hits;
      triangle_tree.all_intersected_primitives(query, std::back_inserter(hits));
      for (TriangleIterator it : hits) {
        double t = 0.0;
        const auto k = static_cast<std::size_t>(it - cgal_triangles.cbegin());
        if constexpr (!kIsPoint) {
          if (!side_is_there(k, query.source(), query.target())) continue;
          t = first_param(a, b, CGAL::intersection(query, *it), 0.0);
        }
        f(cgal_triangle_source[k], t);
      }
    }
    if (!segment_tree.empty()) {
      std::vector<SegmentIterator> hits;
      segment_tree.all_intersected_primitives(query, std::back_inserter(hits));
      for (SegmentIterator it : hits) {
        double t = 0.0;
        if constexpr (!kIsPoint) t = first_param(a, b, CGAL::intersection(query, *it), 0.0);
        f(cgal_segment_source[static_cast<std::size_t>(it - cgal_segments.cbegin())], t);
      }
    }
    for (std::size_t i = 0; i < cgal_points.size(); ++i) {
      bool touch = false;
      if constexpr (kIsPoint) {
        touch = query == cgal_points[i];
      } else {
        touch = query.has_on(cgal_points[i]);
      }
      if (touch) f(cgal_point_source[i], kIsPoint ? 0.0 : param_on(a, b, cgal_points[i]));
    }
  }

  template <class Query>
  bool touches(const Query& query) const {
    if (!exact.empty()) {
      if constexpr (std::is_same_v<Query, Point>) {
        if (exact.signed_distance(to_eigen(query)) <= 0.0) return true;
      } else {
        if (exact.touches(to_eigen(query.source()), to_eigen(query.target()))) return true;
      }
    }
    if constexpr (std::is_same_v<Query, Segment>) {
      if (one_sided && !triangle_tree.empty()) {
        std::vector<TriangleIterator> hits;
        triangle_tree.all_intersected_primitives(query, std::back_inserter(hits));
        for (TriangleIterator it : hits) {
          if (side_is_there(static_cast<std::size_t>(it - cgal_triangles.cbegin()), query.source(), query.target())) {
            return true;
          }
        }
        if (!segment_tree.empty() && segment_tree.do_intersect(query)) return true;
        return std::any_of(cgal_points.begin(), cgal_points.end(), [&](const Point& p) { return query.has_on(p); });
      }
    }
    if (!triangle_tree.empty() && triangle_tree.do_intersect(query)) return true;
    if (!segment_tree.empty() && segment_tree.do_intersect(query)) return true;
    for (const Point& p : cgal_points) {
      if constexpr (std::is_same_v<Query, Point>) {
        if (query == p) return true;
      } else {
        if (query.has_on(p)) return true;
      }
    }
    return false;
  }
};

namespace {

// Distance between a segment and a triangle: 0 where they meet, else attained at an
// endpoint of the segment or on an edge of the triangle.
double segment_triangle_distance(const Segment& s, const Triangle& t) {
  if (CGAL::do_intersect(s, t)) return 0.0;
  double d2 = std::min(CGAL::to_double(CGAL::squared_distance(s.source(), t)),
                       CGAL::to_double(CGAL::squared_distance(s.target(), t)));
  for (int e = 0; e < 3; ++e) {
    d2 = std::min(d2, CGAL::to_double(CGAL::squared_distance(s, Segment(t.vertex(e), t.vertex(e + 1)))));
  }
  return std::sqrt(d2);
}

CGAL::Bbox_3 grown_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r) {
  const Eigen::Vector3d lo = a.cwiseMin(b).array() - r, hi = a.cwiseMax(b).array() + r;
  return {lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()};
}

}  // namespace

bool SurfaceCrossingOracle::segment_brushes_surface(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W,
                                                    double clearance_m) const {
  const Impl& m = *impl_;
  if (m.exact.brushes(a_W, b_W, clearance_m)) return true;
  const Segment s(to_point(a_W), to_point(b_W));
  const Point a = to_point(a_W);
  const CGAL::Bbox_3 box = grown_box(a_W, b_W, clearance_m);
  const double start_clear2 = 4.0 * clearance_m * clearance_m;
  if (!m.triangle_tree.empty()) {
    std::vector<TriangleIterator> near;
    m.triangle_tree.all_intersected_primitives(box, std::back_inserter(near));
    for (TriangleIterator it : near) {
      if (a_W != b_W && segment_triangle_distance(s, *it) < clearance_m &&
          CGAL::to_double(CGAL::squared_distance(a, *it)) > start_clear2) {
        return true;
      }
    }
  }
  if (!m.segment_tree.empty() && a_W != b_W) {
    std::vector<SegmentIterator> near;
    m.segment_tree.all_intersected_primitives(box, std::back_inserter(near));
    for (SegmentIterator it : near) {
      if (CGAL::to_double(CGAL::squared_distance(s, *it)) < clearance_m * clearance_m &&
          CGAL::to_double(CGAL::squared_distance(a, *it)) > start_clear2) {
        return true;
      }
    }
  }
  return false;
}

SurfaceCrossingOracle::SurfaceCrossingOracle(const CollisionWorld& world) : impl_(std::make_unique<Impl>()) {
  std::vector<PlacedMesh> meshes;
  meshes.reserve(static_cast<std::size_t>(world.object_count()));
  for (int i = 0; i < world.object_count(); ++i) {
    meshes.push_back({&world.shape(i).mesh(), world.pose(i), world.touchable(i)});
    const ExactShape* exact = world.exact_shape(i);
    impl_->is_exact.push_back(exact != nullptr);
    if (exact != nullptr) impl_->exact.add(i, *exact, world.pose(i));
  }
  impl_->build(meshes);
}

SurfaceCrossingOracle::SurfaceCrossingOracle(std::span<const PlacedMesh> meshes) : impl_(std::make_unique<Impl>()) {
  impl_->build(meshes);
}

SurfaceCrossingOracle::SurfaceCrossingOracle(const TriangleMesh& mesh, const Pose& X_WO)
    : impl_(std::make_unique<Impl>()) {
  const PlacedMesh placed{&mesh, X_WO};
  impl_->build(std::span<const PlacedMesh>(&placed, 1));
}

SurfaceCrossingOracle::~SurfaceCrossingOracle() = default;
SurfaceCrossingOracle::SurfaceCrossingOracle(SurfaceCrossingOracle&&) noexcept = default;
SurfaceCrossingOracle& SurfaceCrossingOracle::operator=(SurfaceCrossingOracle&&) noexcept = default;

bool SurfaceCrossingOracle::segment_touches_surface(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const {
  if (a_W == b_W) return point_touches_surface(a_W);
  return impl_->touches(Segment(to_point(a_W), to_point(b_W)));
}

bool SurfaceCrossingOracle::point_touches_surface(const Eigen::Vector3d& p_W) const {
  return impl_->touches(to_point(p_W));
}

bool SurfaceCrossingOracle::segment_meets_a_front(const Eigen::Vector3d& a_W, const Eigen::Vector3d& b_W) const {
  const Impl& m = *impl_;
  if (a_W == b_W || m.triangle_tree.empty()) return false;
  const Point a = to_point(a_W);
  std::vector<TriangleIterator> hits;
  m.triangle_tree.all_intersected_primitives(Segment(a, to_point(b_W)), std::back_inserter(hits));
  return std::any_of(hits.begin(), hits.end(), [&](TriangleIterator t) {
    return CGAL::orientation((*t)[0], (*t)[1], (*t)[2], a) == CGAL::POSITIVE;
  });
}

std::vector<OracleHit> SurfaceCrossingOracle::touched_triangles(const Eigen::Vector3d& a_W,
                                                                const Eigen::Vector3d& b_W) const {
  std::vector<std::pair<std::size_t, double>> touched;  // (source, t)
  auto collect = [&](std::size_t source, double t) { touched.emplace_back(source, t); };
  if (a_W == b_W) {
    impl_->for_each_touch(to_point(a_W), a_W, b_W, collect);
  } else {
    impl_->for_each_touch(Segment(to_point(a_W), to_point(b_W)), a_W, b_W, collect);
  }
  // A collinear triangle may be reported once per edge: keep its smallest t.
  std::sort(touched.begin(), touched.end());
  std::vector<OracleHit> hits;
  for (std::size_t i = 0; i < touched.size(); ++i) {
    if (i > 0 && touched[i].first == touched[i - 1].first) continue;
    hits.push_back({impl_->refs[touched[i].first], touched[i].second});
  }
  for (const ExactSolids::Touch& t : impl_->exact.all_touches(a_W, b_W)) {
    hits.push_back({TriangleRef{t.object, kExactSurface}, t.t});
  }
  std::sort(hits.begin(), hits.end(), [](const OracleHit& x, const OracleHit& y) {
    if (x.t != y.t) return x.t < y.t;
    if (x.where.object != y.where.object) return x.where.object < y.where.object;
    return x.where.triangle < y.where.triangle;
  });
  return hits;
}

std::optional<OracleHit> SurfaceCrossingOracle::first_touched_triangle(const Eigen::Vector3d& a_W,
                                                                       const Eigen::Vector3d& b_W) const {
  std::vector<OracleHit> hits = touched_triangles(a_W, b_W);
  if (hits.empty()) return std::nullopt;
  return hits.front();
}

SurfaceSide SurfaceCrossingOracle::side_of_closed_surfaces(const Eigen::Vector3d& p_W) const {
  const Impl& m = *impl_;
  if (!m.exact.empty()) {
    const double d = m.exact.signed_distance(p_W);
    if (d < 0.0) return SurfaceSide::Inside;
    if (d == 0.0) return SurfaceSide::OnSurface;
  }
  if (std::none_of(m.closed.begin(), m.closed.end(), [](bool c) { return c; })) return SurfaceSide::Outside;
  const Point p = to_point(p_W);

  bool on_surface = false;
  m.for_each_touch(p, p_W, p_W, [&](std::size_t source, double) {
    if (m.closed[static_cast<std::size_t>(m.refs[source].object)]) on_surface = true;
  });
  if (on_surface) return SurfaceSide::OnSurface;

  // Cast rays until one crosses every triangle it meets through the interior, away
  // from edges, vertices and supporting planes; then parity per closed object is exact.
  double reach = 1.0;
  for (int corner = 0; corner < 8; ++corner) {
    reach = std::max(reach, (m.bounds_W.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)) - p_W).norm());
  }
  std::mt19937_64 rng(0x5eedULL);
  std::normal_distribution<double> gauss;
  std::vector<TriangleIterator> hits;
  std::vector<unsigned char> parity(m.closed.size());
  for (int attempt = 0; attempt < 256; ++attempt) {
    Eigen::Vector3d d(gauss(rng), gauss(rng), gauss(rng));
    if (d.norm() < 1e-3) continue;
    d.normalize();
    const Point q = to_point(p_W + (2.0 * reach + 1.0) * d);
    hits.clear();
    m.triangle_tree.all_intersected_primitives(Segment(p, q), std::back_inserter(hits));
    std::fill(parity.begin(), parity.end(), 0);
    bool degenerate = false;
    for (TriangleIterator it : hits) {
      const std::size_t object = static_cast<std::size_t>(
          m.refs[m.cgal_triangle_source[static_cast<std::size_t>(it - m.cgal_triangles.cbegin())]].object);
      if (!m.closed[object]) continue;
      const Point& a = it->vertex(0);
      const Point& b = it->vertex(1);
      const Point& c = it->vertex(2);
      if (CGAL::orientation(a, b, c, p) == CGAL::COPLANAR || CGAL::orientation(a, b, c, q) == CGAL::COPLANAR ||
          CGAL::orientation(p, q, a, b) == CGAL::COPLANAR || CGAL::orientation(p, q, b, c) == CGAL::COPLANAR ||
          CGAL::orientation(p, q, c, a) == CGAL::COPLANAR) {
        degenerate = true;
        break;
      }
      parity[object] ^= 1U;
    }
    if (degenerate) continue;
    for (std::size_t object = 0; object < parity.size(); ++object) {
      if (m.closed[object] && (parity[object] != 0) != m.room[object]) return SurfaceSide::Inside;
    }
    return SurfaceSide::Outside;
  }
  throw std::runtime_error("SurfaceCrossingOracle: no non-degenerate parity ray found");
}

bool SurfaceCrossingOracle::point_inside_closed_mesh(const Eigen::Vector3d& p_W) const {
  return side_of_closed_surfaces(p_W) != SurfaceSide::Outside;
}

double SurfaceCrossingOracle::distance_to_surface(const Eigen::Vector3d& p_W) const {
  Impl& m = *impl_;
  std::call_once(m.distance_once, [&m] {
    // The search starts from the nearest of these hints and still finds the nearest
    // triangle, so any set of hints gives the same distance. One triangle in
    // kDistanceHintStride keeps CGAL's hint tree, which would otherwise hold a point per
    // triangle (about 170 bytes a triangle), small.
    if (!m.triangle_tree.empty()) {
      std::vector<TriangleTree::Point_and_primitive_id> hints;
      hints.reserve(m.cgal_triangles.size() / kDistanceHintStride + 1);
      for (std::size_t k = 0; k < m.cgal_triangles.size(); k += kDistanceHintStride) {
        const auto it = m.cgal_triangles.cbegin() + static_cast<std::ptrdiff_t>(k);
        hints.emplace_back(it->vertex(0), it);
      }
      m.triangle_tree.accelerate_distance_queries(hints.cbegin(), hints.cend());
    }
    if (!m.segment_tree.empty()) m.segment_tree.accelerate_distance_queries();
  });
  const Point p = to_point(p_W);
  double d2 = std::numeric_limits<double>::infinity();
  if (!m.triangle_tree.empty()) d2 = std::min(d2, CGAL::to_double(m.triangle_tree.squared_distance(p)));
  if (!m.segment_tree.empty()) d2 = std::min(d2, CGAL::to_double(m.segment_tree.squared_distance(p)));
  for (const Point& q : m.cgal_points) d2 = std::min(d2, CGAL::to_double(CGAL::squared_distance(p, q)));
  return std::min(std::sqrt(d2), std::abs(m.exact.signed_distance(p_W)));
}

bool SurfaceCrossingOracle::is_closed(int object) const {
  return impl_->closed.at(static_cast<std::size_t>(object));
}

int SurfaceCrossingOracle::object_count() const { return static_cast<int>(impl_->closed.size()); }

std::size_t SurfaceCrossingOracle::triangle_count() const { return impl_->triangles_W.size(); }

const std::array<Eigen::Vector3d, 3>& SurfaceCrossingOracle::triangle_W(std::size_t i) const {
  return impl_->triangles_W.at(i);
}

const TriangleRef& SurfaceCrossingOracle::triangle_ref(std::size_t i) const { return impl_->refs.at(i); }

}  // namespace mhd::verify
