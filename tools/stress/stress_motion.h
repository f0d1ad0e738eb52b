#pragma once
// Random rigid motions for the moving-object stress (moving_stress_run.h), one per stroke
// chain, drawn from (seed, object key, chain): a constant twist, or keyframed poses played
// as a loop or back and forth (ping-pong), never faster than the given linear speed (of
// the object's origin, as ObjectMotion::max_speed_mps measures it) and rotation rate.
// Keyframed motions turn about the object's centre and stay within an excursion of where
// they start, so the strokes keep reaching the object; a twist drifts on.
// With the motion comes how the chain's strokes follow the object: each stroke is drawn
// for the object at its starting pose and carried by the object's motion at a time tau(t):
//   Riding:  tau = t, the hand moves with the object (the proxy rides and is dragged);
//   Lagging: tau = max(0, t - lag), the hand follows late, so the object runs into it;
//   Still:   tau = 0, the hand keeps to the world and the object moves through the strokes.

#include "geometry/object_motion.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <numbers>
#include <string_view>

namespace mhd::stress {

enum class MotionKind { Twist, Loop, PingPong };
inline constexpr int kMotionKindCount = 3;
enum class StrokeAnchor { Riding, Lagging, Still };
inline constexpr int kStrokeAnchorCount = 3;
[[nodiscard]] std::string_view to_string(MotionKind kind);
[[nodiscard]] std::string_view to_string(StrokeAnchor anchor);

struct MotionDrawParams {
  double max_speed_mps = 0.5;
  double max_rate_radps = std::numbers::pi;  ///< 180 deg/s
  /// Share of motions at exactly the maximum speed and rate; the others in [5 %, 100 %] of them.
  double full_speed_fraction = 0.3;
  double max_excursion_m = 0.1;        ///< keyframed: how far a key's centre is from the start
  double max_key_turn_rad = 2.0;       ///< keyframed: how far a key is turned from the start
  double max_lag_s = 0.3;              ///< Lagging strokes' largest lag
  double weight_twist = 1.0, weight_loop = 1.0, weight_pingpong = 1.0;
  double weight_riding = 1.0, weight_lagging = 2.0, weight_still = 1.0;
};

struct StressMotion {
  MotionKind kind = MotionKind::Twist;
  ObjectMotion motion;  ///< X_WO_at(0) is the object's starting pose
  StrokeAnchor anchor = StrokeAnchor::Riding;
  double lag_s = 0.0;   ///< Lagging only
  /// The motion time at which the strokes' frame is taken at chain time t_s (see above).
  [[nodiscard]] double anchor_time_s(double t_s) const noexcept;
};

/// The motion of chain `chain_first` (its first stroke's index). The object starts at
/// X_WO_0; keyframed motions turn about p_W_centre (the object's centre at the start).
/// Postcondition: motion.max_speed_mps() <= max_speed_mps and motion.max_rate_radps() <=
/// max_rate_radps (to rounding). Precondition: speeds and excursions >= 0.
[[nodiscard]] StressMotion draw_stress_motion(std::uint64_t seed, std::uint64_t object_key, std::size_t chain_first,
                                              const Pose& X_WO_0, const Eigen::Vector3d& p_W_centre,
                                              const MotionDrawParams& params);

}  // namespace mhd::stress
