#pragma once
// The base motion planner (thesis ch. 3): keeps the user's hand (the HIP) inside the arm's
// usable workspace by moving the omnidirectional base, and never moves the base into the
// user. The haptic server calls update() once per planner tick (10 Hz) and sends the
// returned twist to the base plugin until the next tick.
//
// Configuration space (x, z, heading): the user is a cylinder of radius robot radius +
// human radius. The target is on the line from the user through the hand at
// d' = arm length + robot radius, and the base turns so that the device faces the user.
// Two planners share this interface:
//   seed        the thesis's algorithm (Table 3.1 as reconstructed in docs/planner.md):
//               escape / straight / sub-targets every pi', speed proportional to distance
//               within a deceleration interval, 50 mm stop interval; acts only once the
//               HIP leaves the usable workspace.
//   predictive  MHD's: extrapolates the user's tracked velocity, goes straight whenever the
//               straight path clears the user, otherwise takes the largest sub-target step
//               that does, and moves at full speed up to a one-tick (deadbeat) stop.
// Both end with the same guard: within the safety band around the user's cylinder no
// velocity component points at the user, and the command never exceeds the limits.
//
// update() is noexcept, allocation-free and deterministic; a planner holds only whether it is
// currently moving (the activation hysteresis). Frames: W is the world (y up), B the base
// (x forward, z = x cross y, the right side); see kinematics/base_pose.h.

#include "kinematics/base_pose.h"
#include "planner/keep_outs.h"
#include "planner/planner_settings.h"

#include <Eigen/Core>

#include <memory>
#include <string_view>

namespace mhd {

/// Which case of Table 3.1 produced a command (for logging).
enum class PlannerCase {
  Idle,       ///< HIP inside the usable workspace, base not moving
  Escape,     ///< base inside the user's cylinder: straight away from the user
  Straight,   ///< angle to the target below pi' (seed) or straight path clear (predictive)
  SubTarget,  ///< moving to a temporary target on the circle of radius d' around the user
  Stopping,   ///< within the stop interval of the target: linear velocity 0, finishing the turn
  Held,       ///< the keep-outs are not current (another rig's data is stale): the base stands still
};

[[nodiscard]] std::string_view to_string(PlannerCase c) noexcept;

struct PlannerInput {
  double time_s = 0.0;
  BasePose base;                                          ///< X_WB, planar
  Eigen::Vector2d user_W = Eigen::Vector2d::Zero();       ///< user's body centre (world x, z)
  double user_heading_rad = 0.0;                          ///< user's facing, forward (cos h, 0, -sin h)
  Eigen::Vector2d user_velocity_W = Eigen::Vector2d::Zero();  ///< (vx, vz) from the tracker; 0 if unknown
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();      ///< the HIP (the user's hand) in the world
  KeepOuts keep_outs;  ///< the other users and bases on the floor (none in a one-rig scene)
  /// False when a source of keep_outs went stale: the base cannot see what it must avoid.
  bool keep_outs_current = true;
};

struct PlannerOutput {
  BaseTwist twist_B;  ///< command until the next update
  PlannerCase status = PlannerCase::Idle;
  Eigen::Vector2d target_W = Eigen::Vector2d::Zero();  ///< final target (x, z) (valid unless Idle)
  Eigen::Vector2d goal_W = Eigen::Vector2d::Zero();    ///< point steered at this tick (sub-target or target)
  double goal_heading_rad = 0.0;                       ///< heading that faces the user
  bool hip_in_usable = true;                           ///< HIP inside the usable workspace (planar)
  bool guard_active = false;                           ///< the guard removed motion towards the user
};

/// What every planner reads first: the base and the hand in world (x, z), and its output
/// with hip_in_usable set.
struct PlanarStart {
  PlannerOutput out;
  Eigen::Vector2d base_W;
  Eigen::Vector2d hand_W;
};
[[nodiscard]] PlanarStart planar_start(const PlannerInput& in, const PlannerSettings& settings) noexcept;

class Planner {
 public:
  explicit Planner(const PlannerSettings& settings) : settings_(settings) {}
  virtual ~Planner() = default;
  Planner(const Planner&) = delete;
  Planner& operator=(const Planner&) = delete;

  /// One planner tick. Call every settings().command_period_s with the latest measurements.
  /// Keep-outs that are not current hold the base (PlannerCase::Held, a zero twist) and
  /// forget that it was moving; otherwise the planner's own step.
  [[nodiscard]] PlannerOutput update(const PlannerInput& input) noexcept;
  /// Forgets whether the base is moving (e.g. after the base was stopped externally).
  void reset() noexcept { active_ = false; }
  [[nodiscard]] bool active() const noexcept { return active_; }
  [[nodiscard]] virtual PlannerKind kind() const noexcept = 0;
  [[nodiscard]] const PlannerSettings& settings() const noexcept { return settings_; }

 protected:
  PlannerSettings settings_;
  bool active_ = false;

 private:
  [[nodiscard]] virtual PlannerOutput plan(const PlannerInput& input) noexcept = 0;
};

/// Precondition: validate(settings) is empty.
[[nodiscard]] std::unique_ptr<Planner> make_planner(PlannerKind kind, const PlannerSettings& settings);

}  // namespace mhd
