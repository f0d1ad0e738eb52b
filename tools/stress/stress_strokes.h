#pragma once
// Random fast HIP strokes aimed at one object of a scene, for the pop-through stress
// tool. Each stroke is drawn from its own random stream (seed, object key, stroke index),
// so one stroke can be rebuilt without drawing the ones before it. Kinds:
//   Through: into the surface at a random angle and on through the object and out;
//   Poke:    into the surface at a random angle, 100-300 ms, sometimes back out;
//   Graze:   nearly tangent (-1 to +5 deg), a few mm above or below the surface;
//   Ridge:   into a convex edge or an open rim while sliding along or across it;
//   Crease:  into a concave edge (two faces meeting inside 180 deg) while sliding;
//   Vertex:  into a corner where three or more feature edges meet;
//   Random:  from a random free point near the object in a random direction;
//   Tour:    one leg of a continuous tour (tour_strokes.cpp): a free-space transit
//            around the object from where the last tour stroke left the HIP, approach
//            along the normal, push 20-50 mm deep, slide, retract along the normal.
// Every stroke starts in free space: clear of every triangle by 0.1 mm, outside every
// closed object (exact oracle) and outside by the engine's own containment test (the
// haptic server will not start the proxy otherwise). A stroke that continues the one
// before it starts at the nearest of a few draws and is joined to it by a straight
// connector at the maximum speed; one that would start too far away resets instead.

#include "collision/collision_world.h"
#include "verification/surface_crossing_oracle.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace mhd::stress {

enum class StrokeKind { Through, Poke, Graze, Ridge, Crease, Vertex, Random, Tour };
inline constexpr int kStrokeKindCount = 8;
[[nodiscard]] std::string_view to_string(StrokeKind kind);

/// An edge of the surface where the direction of the surface turns (a ridge, crease or
/// open rim), or a corner vertex: a point q, the edge direction (zero for a vertex) and
/// the unit direction pointing away from the surface into free space.
struct SurfaceFeature {
  Eigen::Vector3d a_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d b_W = Eigen::Vector3d::Zero();  ///< == a_W for a vertex
  Eigen::Vector3d out_W = Eigen::Vector3d::UnitY();
  bool rim = false;  ///< an open boundary edge (out_W then lies in its triangle's plane)
};

/// One object's triangles in the world frame with what the stroke kinds aim at.
struct ObjectSurface {
  int object = -1;
  bool closed = false;  ///< has an inside (open sheets are touched from both sides)
  std::vector<std::array<Eigen::Vector3d, 3>> triangles_W;
  std::vector<Eigen::Vector3d> normals_W;  ///< unit, CCW (zero for degenerate triangles)
  std::vector<double> cumulative_area;
  std::vector<SurfaceFeature> ridges;   ///< convex edges and open rims
  std::vector<SurfaceFeature> creases;  ///< concave edges
  std::vector<SurfaceFeature> corners;  ///< vertices on three or more feature edges
  Eigen::AlignedBox3d bounds_W;
};

/// Builds the surface of `object`. Feature edges are those whose two faces turn by more
/// than `feature_angle_rad`, edges with one face (rims) and edges with more than two.
/// Vertices are matched by position, so meshes that repeat corners per face work too.
[[nodiscard]] ObjectSurface make_object_surface(const CollisionWorld& world, int object, bool closed,
                                                double feature_angle_rad = 0.35);

/// Tour strokes (tour_strokes.cpp).
struct TourParams {
  /// Share of chains that are tours (every stroke of such a chain is a Tour).
  double chain_fraction = 0.3;
  double min_depth_m = 0.02, max_depth_m = 0.05;  ///< push below the surface
  double min_slide_m = 0.01, max_slide_m = 0.08;  ///< tangential travel while pressed in
  double min_approach_m = 0.01, max_approach_m = 0.04;
  /// The free-space transit keeps this far from every surface at its waypoints and
  /// samples (its segments are also checked exactly), and retracts end this far out.
  double clearance_m = 0.005;
  /// Objects whose bounding sphere is larger are toured locally (the next target is the
  /// nearest of a few draws, the transit a lifted arc) instead of around the whole object.
  double max_around_radius_m = 0.4;
  int max_transit_attempts = 24;
};

struct StressStrokeParams {
  double max_speed_m_per_s = 1.5;
  double rate_Hz = 1000.0;
  double min_duration_s = 0.1;
  double max_duration_s = 0.3;
  /// Fraction of strokes at exactly max speed; the rest are uniform in [5 %, 100 %].
  double full_speed_fraction = 0.3;
  double min_start_clearance_m = 1e-4;
  /// Through strokes go on past the entry point by up to this much (and at least the
  /// object's size, where that is smaller).
  double max_through_m = 0.6;
  /// Random starts are drawn in the object's bounds grown by this.
  double random_margin_m = 0.05;
  int max_attempts = 200;
  /// A continuing stroke takes the nearest start of this many draws, and continues only
  /// if that is within max_connector_m of the HIP (else the proxy is reset).
  int continue_candidates = 8;
  double max_connector_m = 0.3;
  TourParams tour;
};

struct StressStroke {
  StrokeKind kind = StrokeKind::Random;
  std::size_t index = 0;
  /// HIP samples, one per tick. A continuing stroke starts with its connector: the
  /// samples after the previous stroke's last one up to this stroke's start.
  std::vector<Eigen::Vector3d> p_W_hip;
  std::size_t connector_samples = 0;
  /// Continues the previous stroke without a proxy reset (p_W_hip starts with the connector).
  bool continues = false;
  Eigen::Vector3d start_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction_W = Eigen::Vector3d::Zero();
  double speed_m_per_s = 0.0;
  int attempts = 0;  ///< draws until a free start was found
  /// Tour strokes: where the push reached (HIP deepest below the target point), and
  /// where the retract ended (in free space, at least the tour clearance out).
  Eigen::Vector3d push_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d retract_W = Eigen::Vector3d::Zero();
  int transit_attempts = 0;  ///< transits drawn until one was free (0: no transit)
};

/// Stable 64-bit key of a name (FNV-1a), for per-object random streams.
[[nodiscard]] std::uint64_t name_key(std::string_view name);

class StressStrokeGenerator {
 public:
  /// Keeps references to all four arguments.
  StressStrokeGenerator(const CollisionWorld& world, const verify::SurfaceCrossingOracle& scene_oracle,
                        const ObjectSurface& surface, const StressStrokeParams& params);

  /// Stroke `index` of the stream (seed, object_key). With `continue_from` (the last HIP
  /// of the previous stroke) the stroke tries to continue from there (see `continues`).
  /// Throws std::runtime_error if no free start is found.
  [[nodiscard]] StressStroke make(std::uint64_t seed, std::uint64_t object_key, std::size_t index,
                                  const std::optional<Eigen::Vector3d>& continue_from) const;

  /// Whether the chain whose first stroke is `chain_first` is a tour (deterministic per
  /// (seed, object_key, chain_first); about params.tour.chain_fraction of chains).
  [[nodiscard]] bool is_tour_chain(std::uint64_t seed, std::uint64_t object_key, std::size_t chain_first) const;

  /// Stroke `index` as a Tour (tour_strokes.cpp): with `continue_from` (where the last
  /// tour stroke left the HIP, in free space) it starts with a free-space transit from
  /// there; without, or when no free transit is found, the proxy is reset at its start.
  /// Throws std::runtime_error if no target with a free approach is found.
  [[nodiscard]] StressStroke make_tour(std::uint64_t seed, std::uint64_t object_key, std::size_t index,
                                       const std::optional<Eigen::Vector3d>& continue_from) const;

  /// Whether the proxy may be started at p (see the header comment).
  [[nodiscard]] bool start_is_free(const Eigen::Vector3d& p_W) const;

 private:
  const CollisionWorld& world_;
  const verify::SurfaceCrossingOracle& oracle_;
  const ObjectSurface& surface_;
  StressStrokeParams params_;
  std::vector<SurfaceFeature> rims_;           ///< surface_.ridges that are open rims
  std::vector<SurfaceFeature> convex_ridges_;  ///< ... and the others
};

}  // namespace mhd::stress
