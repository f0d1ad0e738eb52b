#include "stress/stress_strokes.h"

#include "collision/point_containment.h"
#include "stress/stroke_random.h"
#include "verification/stroke_set.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace mhd::stress {
namespace {

using Eigen::Vector3d;

struct PositionHash {
  std::size_t operator()(const Vector3d& p) const {
    std::uint64_t h = 0;
    for (int i = 0; i < 3; ++i) h = splitmix64(h ^ std::bit_cast<std::uint64_t>(p[i] + 0.0));  // -0 == +0
    return static_cast<std::size_t>(h);
  }
};

struct EdgeEntry {
  std::uint64_t key = 0;  // (low welded id << 32) | high welded id
  std::uint32_t triangle = 0;
  std::uint32_t opposite = 0;  // welded id of the triangle's third corner
};

}  // namespace

std::string_view to_string(StrokeKind kind) {
  switch (kind) {
    case StrokeKind::Through: return "through";
    case StrokeKind::Poke: return "poke";
    case StrokeKind::Graze: return "graze";
    case StrokeKind::Ridge: return "ridge";
    case StrokeKind::Crease: return "crease";
    case StrokeKind::Vertex: return "vertex";
    case StrokeKind::Random: return "random";
    case StrokeKind::Tour: return "tour";
  }
  return "?";
}

std::uint64_t name_key(std::string_view name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

ObjectSurface make_object_surface(const CollisionWorld& world, int object, bool closed, double feature_angle_rad) {
  ObjectSurface s;
  s.object = object;
  s.closed = closed;
  const MeshBvh& shape = world.shape(object);
  const TriangleMesh& mesh = shape.mesh();
  const Pose& X_WO = world.pose(object);

  // Weld corners by exact position (world frame), so faces that repeat corners still
  // share edges.
  std::unordered_map<Vector3d, std::uint32_t, PositionHash> ids;
  std::vector<Vector3d> welded;
  std::vector<std::uint32_t> id_of_vertex(mesh.vertices_m.size());
  for (std::size_t v = 0; v < mesh.vertices_m.size(); ++v) {
    const Vector3d p = X_WO * mesh.vertices_m[v];
    auto [it, inserted] = ids.try_emplace(p, static_cast<std::uint32_t>(welded.size()));
    if (inserted) welded.push_back(p);
    id_of_vertex[v] = it->second;
  }

  const std::size_t n = mesh.triangles.size();
  s.triangles_W.reserve(n);
  s.normals_W.reserve(n);
  s.cumulative_area.reserve(n);
  std::vector<EdgeEntry> edges;
  edges.reserve(3 * n);
  std::vector<Vector3d> vertex_normal(welded.size(), Vector3d::Zero());
  double total = 0.0;
  for (std::size_t t = 0; t < n; ++t) {
    const TriangleIndices& tri = mesh.triangles[t];
    const std::array<Vector3d, 3> v{X_WO * mesh.vertices_m[tri[0]], X_WO * mesh.vertices_m[tri[1]],
                                    X_WO * mesh.vertices_m[tri[2]]};
    const Vector3d area_normal = (v[1] - v[0]).cross(v[2] - v[0]);
    const double twice_area = area_normal.norm();
    s.triangles_W.push_back(v);
    s.normals_W.push_back(twice_area > 0.0 ? Vector3d(area_normal / twice_area) : Vector3d::Zero());
    total += 0.5 * twice_area;
    s.cumulative_area.push_back(total);
    if (!(twice_area > 0.0)) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = id_of_vertex[tri[static_cast<std::size_t>(k)]];
      const std::uint32_t b = id_of_vertex[tri[static_cast<std::size_t>((k + 1) % 3)]];
      const std::uint32_t c = id_of_vertex[tri[static_cast<std::size_t>((k + 2) % 3)]];
      vertex_normal[a] += area_normal;
      if (a == b) continue;
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      edges.push_back(EdgeEntry{key, static_cast<std::uint32_t>(t), c});
    }
  }
  s.bounds_W = Eigen::AlignedBox3d();
  for (const Vector3d& p : welded) s.bounds_W.extend(p);

  std::sort(edges.begin(), edges.end(), [](const EdgeEntry& x, const EdgeEntry& y) {
    return x.key < y.key || (x.key == y.key && x.triangle < y.triangle);
  });
  std::vector<int> feature_edges_at(welded.size(), 0);
  const double cos_feature = std::cos(feature_angle_rad);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    const auto ia = static_cast<std::uint32_t>(edges[i].key >> 32);
    const auto ib = static_cast<std::uint32_t>(edges[i].key & 0xffffffffULL);
    const Vector3d& a = welded[ia];
    const Vector3d& b = welded[ib];
    const Vector3d e = (b - a).normalized();
    const Vector3d& n1 = s.normals_W[edges[i].triangle];
    bool feature = false;
    if (j - i == 1) {
      // Open rim: free space lies beyond the edge, away from the triangle.
      Vector3d out = e.cross(n1);
      if (out.dot(welded[edges[i].opposite] - a) > 0.0) out = -out;
      s.ridges.push_back(SurfaceFeature{a, b, out.normalized(), true});
      feature = true;
    } else if (j - i == 2) {
      const Vector3d& n2 = s.normals_W[edges[i + 1].triangle];
      const Vector3d sum = n1 + n2;
      if (n1.dot(n2) < cos_feature && sum.norm() > 1e-6) {
        const bool convex = n1.dot(welded[edges[i + 1].opposite] - a) < 0.0;
        (convex ? s.ridges : s.creases).push_back(SurfaceFeature{a, b, sum.normalized()});
        feature = true;
      }
    }
    if (feature) {
      ++feature_edges_at[ia];
      ++feature_edges_at[ib];
    }
    i = j;
  }
  for (std::size_t v = 0; v < welded.size(); ++v) {
    if (feature_edges_at[v] >= 3 && vertex_normal[v].norm() > 0.0) {
      s.corners.push_back(SurfaceFeature{welded[v], welded[v], vertex_normal[v].normalized()});
    }
  }
  return s;
}

StressStrokeGenerator::StressStrokeGenerator(const CollisionWorld& world, const verify::SurfaceCrossingOracle& scene_oracle,
                                             const ObjectSurface& surface, const StressStrokeParams& params)
    : world_(world), oracle_(scene_oracle), surface_(surface), params_(params) {
  if (surface_.cumulative_area.empty() || !(surface_.cumulative_area.back() > 0.0)) {
    throw std::runtime_error("StressStrokeGenerator: object " + std::to_string(surface.object) + " has no area");
  }
  for (const SurfaceFeature& f : surface_.ridges) (f.rim ? rims_ : convex_ridges_).push_back(f);
}

bool StressStrokeGenerator::start_is_free(const Vector3d& p_W) const {
  if (!p_W.allFinite()) return false;
  if (oracle_.distance_to_surface(p_W) < params_.min_start_clearance_m) return false;
  if (oracle_.point_inside_closed_mesh(p_W)) return false;
  return !point_inside_surface(world_, p_W);
}

bool StressStrokeGenerator::is_tour_chain(std::uint64_t seed, std::uint64_t object_key, std::size_t chain_first) const {
  // Its own stream (salted), so the strokes' streams are not disturbed.
  std::mt19937_64 rng(splitmix64(seed ^ splitmix64(object_key ^ splitmix64(static_cast<std::uint64_t>(chain_first) ^
                                                                             0x746f7572ULL))));
  return verify::uniform01(rng) < params_.tour.chain_fraction;
}

StressStroke StressStrokeGenerator::make(std::uint64_t seed, std::uint64_t object_key, std::size_t index,
                                         const std::optional<Vector3d>& continue_from) const {
  std::mt19937_64 rng(splitmix64(seed ^ splitmix64(object_key ^ splitmix64(static_cast<std::uint64_t>(index)))));
  const ObjectSurface& s = surface_;
  const double diag = s.bounds_W.diagonal().norm();

  // Kind by weight; kinds whose features the object lacks fall back to a surface kind.
  const double pick = uniform_in(rng, 0.0, 100.0);
  StrokeKind kind = pick < 20   ? StrokeKind::Through
                    : pick < 35 ? StrokeKind::Poke
                    : pick < 55 ? StrokeKind::Graze
                    : pick < 70 ? StrokeKind::Ridge
                    : pick < 80 ? StrokeKind::Crease
                    : pick < 85 ? StrokeKind::Vertex
                                : StrokeKind::Random;
  if (kind == StrokeKind::Vertex && s.corners.empty()) kind = StrokeKind::Ridge;
  if (kind == StrokeKind::Crease && s.creases.empty()) kind = StrokeKind::Poke;
  if (kind == StrokeKind::Ridge && s.ridges.empty()) kind = StrokeKind::Graze;

  auto surface_point = [&](Vector3d& p, Vector3d& n) { draw_surface_point(s, rng, p, n); };

  struct Draw {
    Vector3d start = Vector3d::Zero();
    Vector3d d = Vector3d::Zero();
    double speed = 0.0;
    std::vector<Vector3d> corners;
  };
  auto draw = [&](StrokeKind k) {
    Draw g;
    g.speed = verify::uniform01(rng) < params_.full_speed_fraction
                  ? params_.max_speed_m_per_s
                  : uniform_in(rng, k == StrokeKind::Through ? 0.5 : 0.05, 1.0) * params_.max_speed_m_per_s;
    const double length = g.speed * uniform_in(rng, params_.min_duration_s, params_.max_duration_s);
    Vector3d& start = g.start;
    Vector3d& d = g.d;
    switch (k) {
      case StrokeKind::Through:
      case StrokeKind::Poke: {
        Vector3d p, n;
        surface_point(p, n);
        const double grazing = uniform_in(rng, k == StrokeKind::Through ? 0.05 : 0.02, std::numbers::pi / 2);
        const double azimuth = uniform_in(rng, 0.0, 2.0 * std::numbers::pi);
        const Vector3d u = any_perpendicular(n);
        const Vector3d t = std::cos(azimuth) * u + std::sin(azimuth) * n.cross(u);
        d = (std::cos(grazing) * t - std::sin(grazing) * n).normalized();
        const bool back_out = k == StrokeKind::Poke && verify::uniform01(rng) < 0.5;
        const double path = back_out ? 0.5 * length : length;
        const double before = std::max(0.002, uniform_in(rng, 0.1, 0.5) * path);
        double after = std::max(0.001, path - before);
        if (k == StrokeKind::Through) {
          after = std::max(after, std::min(uniform_in(rng, 0.3, 1.2) * diag, params_.max_through_m));
        }
        start = p - before * d;
        g.corners = {start, p + after * d};
        if (back_out) g.corners.push_back(start);
        break;
      }
      case StrokeKind::Graze: {
        Vector3d p, n;
        surface_point(p, n);
        const double grazing = uniform_in(rng, -0.017, 0.087);
        const double azimuth = uniform_in(rng, 0.0, 2.0 * std::numbers::pi);
        const double height = uniform_in(rng, -0.002, 0.003);
        const Vector3d u = any_perpendicular(n);
        const Vector3d t = std::cos(azimuth) * u + std::sin(azimuth) * n.cross(u);
        d = (std::cos(grazing) * t - std::sin(grazing) * n).normalized();
        start = p + height * n - uniform_in(rng, 0.2, 0.8) * length * d;
        g.corners = {start, start + length * d};
        break;
      }
      case StrokeKind::Ridge:
      case StrokeKind::Crease:
      case StrokeKind::Vertex: {
        const std::vector<SurfaceFeature>& list = k == StrokeKind::Ridge    ? s.ridges
                                                  : k == StrokeKind::Crease ? s.creases
                                                                            : s.corners;
        const SurfaceFeature& f = draw_feature(list, rng);
        const Vector3d q = f.a_W + verify::uniform01(rng) * (f.b_W - f.a_W);
        if (k == StrokeKind::Vertex) {
          d = (-f.out_W + uniform_in(rng, 0.0, 1.2) * random_unit(rng)).normalized();
        } else {
          const Vector3d e = (f.b_W - f.a_W).normalized();
          const Vector3d w = e.cross(f.out_W);
          // Press into the edge while sliding along it and rolling over it.
          d = (-uniform_in(rng, 0.3, 1.0) * f.out_W + uniform_in(rng, -1.0, 1.0) * e + uniform_in(rng, -1.2, 1.2) * w)
                  .normalized();
        }
        start = q - uniform_in(rng, 0.2, 0.6) * length * d + uniform_in(rng, 0.0, 0.002) * f.out_W;
        g.corners = {start, start + length * d};
        break;
      }
      case StrokeKind::Random:
      case StrokeKind::Tour: {  // tours are made by make_tour(); never drawn here
        const Vector3d lo = s.bounds_W.min() - Vector3d::Constant(params_.random_margin_m);
        const Vector3d hi = s.bounds_W.max() + Vector3d::Constant(params_.random_margin_m);
        for (int a = 0; a < 3; ++a) start[a] = uniform_in(rng, lo[a], hi[a]);
        d = random_unit(rng);
        g.corners = {start, start + length * d};
        break;
      }
    }
    return g;
  };

  StressStroke stroke;
  stroke.index = index;
  for (int attempt = 0; attempt < 2 * params_.max_attempts; ++attempt) {
    if (attempt == params_.max_attempts) kind = StrokeKind::Random;  // the object's surface is crowded
    Draw g = draw(kind);
    if (continue_from) {
      // Continue near where the HIP is: the nearest of a few draws.
      for (int c = 1; c < params_.continue_candidates; ++c) {
        Draw other = draw(kind);
        if ((other.start - *continue_from).squaredNorm() < (g.start - *continue_from).squaredNorm()) g = std::move(other);
      }
    }
    if (!g.d.allFinite() || !start_is_free(g.start)) continue;
    stroke.kind = kind;
    stroke.start_W = g.start;
    stroke.direction_W = g.d;
    stroke.speed_m_per_s = g.speed;
    stroke.attempts = attempt + 1;
    stroke.continues = continue_from && (*continue_from - g.start).norm() <= params_.max_connector_m;
    if (stroke.continues && (*continue_from - g.start).norm() > 0.0) {
      const std::array<Vector3d, 2> connector{*continue_from, g.start};
      std::vector<Vector3d> join = verify::sample_polyline(connector, params_.max_speed_m_per_s, params_.rate_Hz);
      stroke.p_W_hip.assign(join.begin() + 1, join.end() - 1);  // the stroke's own samples start at `start`
      stroke.connector_samples = stroke.p_W_hip.size();
    }
    const std::vector<Vector3d> own = verify::sample_polyline(g.corners, g.speed, params_.rate_Hz);
    stroke.p_W_hip.insert(stroke.p_W_hip.end(), own.begin(), own.end());
    return stroke;
  }
  throw std::runtime_error("stress strokes: no free start found for stroke " + std::to_string(index) + " in " +
                           std::to_string(2 * params_.max_attempts) + " draws");
}

}  // namespace mhd::stress
