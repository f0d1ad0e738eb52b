#pragma once
// The free-space leg of a tour (tour_strokes.cpp): a path for the HIP from where one
// tour stroke retracted to where the next one approaches, around the object (through
// points on a sphere round its bounds, sometimes behind it or just past an open rim)
// and never through any surface of the scene. Every leg is checked with the exact
// oracle, waypoints and samples along the legs keep a clearance, and a path that fails
// is drawn again. On these ticks the HIP is in free space, so a proxy that does not
// follow it is a follow failure (verification/follow_check.h).

#include "stress/stress_strokes.h"
#include "verification/surface_crossing_oracle.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <random>
#include <vector>

namespace mhd::stress {

/// One end of a transit: a free point and the unit direction to leave or reach it by
/// (zero: any; a direction is drawn per attempt, the first radial from the bounds' centre).
struct TransitEnd {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d out_W = Eigen::Vector3d::Zero();
};

struct TransitRequest {
  TransitEnd from, to;
  Eigen::AlignedBox3d bounds_W;  ///< of the toured object
  /// Around the object's bounding sphere; false (large objects): a lifted arc between the ends.
  bool around = true;
  const std::vector<SurfaceFeature>* rims = nullptr;  ///< open boundary edges to pass behind, or none
};

struct Transit {
  std::vector<Eigen::Vector3d> corners_W;  ///< from.p_W ... to.p_W
  int attempts = 0;
};

/// Draws transits until one passes (see the header comment); nullopt after
/// params.max_transit_attempts failures.
[[nodiscard]] std::optional<Transit> plan_free_transit(const verify::SurfaceCrossingOracle& oracle,
                                                       const TransitRequest& request, const TourParams& params,
                                                       std::mt19937_64& rng);

/// Whether the leg a -> b touches no surface (exact) and its samples (spaced at most
/// max(clearance, |b - a| / 8) apart, ends excluded) are clearance / 2 from every surface.
[[nodiscard]] bool leg_is_clear(const verify::SurfaceCrossingOracle& oracle, const Eigen::Vector3d& a_W,
                                const Eigen::Vector3d& b_W, double clearance_m);

}  // namespace mhd::stress
