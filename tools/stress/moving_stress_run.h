#pragma once
// The stress with a moving target: each stroke chain gives one object of a
// compiled scene a random motion (stress_motion.h) and throws the usual stress strokes
// (stress_strokes.h: chains, tours, free-space joins) at it while it moves. Each stroke is
// drawn for the object at its starting pose and carried by the object's motion (the
// chain's anchor: riding, lagging or still), so it reaches the moving surface. The other
// objects stay at their poses at t = 0. Every tick runs as the haptic tick does (objects
// moved and the proxy carried by MovingWorld, then step_proxy with the objects' twists) and
// is judged exactly in each object's frame (verification/moving_tick_check.h): crossings,
// ticks inside, follow failures, free-space force. A proxy reset (a chain's start, or a
// stroke too far to join) restarts the motion's clock: the object is put back at its
// start with the proxy in free space, as at the haptic server's start-up. A proxy squeezed
// between the moving object and a still one may be overlapped by the moving one, by design
// (docs/proxy.md): those ticks are counted apart (overlap_ticks), never the still object's.
// With MoverKind::Pushed the object is instead a rigid body the proxy's force pushes, as
// the haptic server pushes it (pushed_mover.h), thrown at each reset with the drawn
// twist's starting velocity; the strokes follow it as a hand would.

#include "scene_compiler/compiled_scene.h"
#include "stress/pushed_mover.h"
#include "stress/stress_motion.h"
#include "stress/stress_strokes.h"
#include "verification/moving_tick_check.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace mhd::stress {

/// What moves the stressed object: its drawn motion, or the hand (a pushed body thrown at
/// each proxy reset with the drawn motion's starting twist: pushed_mover.h).
enum class MoverKind { Scripted, Pushed };

struct MovingStressSettings {
  MoverKind mover = MoverKind::Scripted;
  PushedBodyParams pushed;  ///< Pushed only
  std::size_t strokes = 100000;
  std::uint64_t seed = 1;
  std::size_t chain_length = 8;  ///< strokes per chain (and per motion); 1 resets before every stroke
  StressStrokeParams stroke;
  MotionDrawParams motion;
  std::size_t max_failures_kept = 10;
  /// For the checker's own tests only: the objects move to their new poses and the proxy
  /// is left where it was (a broken engine: no carry, no relative sweep).
  bool fault_skip_carry = false;
};

/// The first failing tick of one stroke.
struct MovingStrokeFailure {
  std::size_t stroke = 0;
  StrokeKind kind = StrokeKind::Random;
  MotionKind motion = MotionKind::Twist;
  std::size_t tick = 0;  ///< within the stroke (connector samples included)
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();
  verify::MovingTickVerdict verdict;
};

struct MovingStressReport {
  std::string object_name;
  std::size_t triangles = 0;
  bool closed = false;
  std::size_t strokes = 0;
  std::array<std::size_t, kStrokeKindCount> strokes_by_kind{};
  std::size_t chains = 0;
  std::array<std::size_t, kMotionKindCount> chains_by_motion{};
  std::array<std::size_t, kStrokeAnchorCount> chains_by_anchor{};
  std::size_t resets = 0;
  std::size_t ticks = 0;
  std::size_t contact_ticks = 0;
  std::size_t push_ticks = 0;     ///< a moving surface pushed the free proxy
  std::size_t squeeze_ticks = 0;  ///< the carried proxy was stopped by another surface
  std::size_t ride_ticks = 0;     ///< the proxy rested on a moving surface and rode with it
  /// Ticks the moving object overlapped a proxy it had squeezed against a still surface,
  /// by design (docs/proxy.md): not crossings, from the squeeze until the proxy is clear.
  std::size_t overlap_ticks = 0;
  std::size_t strokes_with_push = 0;
  std::size_t crossing_ticks = 0;
  std::size_t inside_ticks = 0;
  std::size_t not_followed_ticks = 0;
  std::size_t free_force_ticks = 0;
  std::size_t failing_strokes = 0;
  /// The fastest motion drawn (origin speed, rotation rate) and a bound on the fastest
  /// surface point: speed + rate * (farthest vertex from the origin).
  double max_object_speed_mps = 0.0;
  double max_object_rate_radps = 0.0;
  double max_surface_speed_mps = 0.0;
  /// Reached, tick by tick (for a pushed body, what the throws and the hand gave it): the
  /// object's fastest origin speed and rotation rate, the bound on its fastest surface
  /// point, and its origin's farthest distance from its start.
  double max_reached_speed_mps = 0.0;
  double max_reached_rate_radps = 0.0;
  double max_reached_surface_speed_mps = 0.0;
  double max_travel_m = 0.0;
  /// Ticks the proxy pressed on the stressed object (it pushes a pushed body back).
  std::size_t object_force_ticks = 0;
  double max_hip_depth_m = 0.0;  ///< largest HIP-proxy distance in contact
  /// The stroke with the most push ticks (to --replay-stroke a clean run's hardest stroke).
  std::size_t busiest_stroke = 0;
  std::size_t busiest_stroke_pushes = 0;
  double seconds = 0.0;
  std::vector<MovingStrokeFailure> failures;  ///< the first max_failures_kept failing strokes
  [[nodiscard]] bool clean() const { return failing_strokes == 0; }
};

/// Runs strokes [0, settings.strokes) at `object` of `scene` (its world holds every object
/// at t = 0). `object_key` names the random streams (name_key of "scene/object").
[[nodiscard]] MovingStressReport stress_moving_object(const CompiledScene& scene, int object, std::uint64_t object_key,
                                                      const MovingStressSettings& settings);

/// Reruns the chain that holds stroke `stroke` up to and including it, printing the
/// chain's motion and every tick of that stroke to `out`.
MovingStressReport replay_moving_stroke(const CompiledScene& scene, int object, std::uint64_t object_key,
                                        const MovingStressSettings& settings, std::size_t stroke, std::FILE* out);

}  // namespace mhd::stress
