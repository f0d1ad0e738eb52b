#pragma once
// A scripted rigid motion of a scene object: keyframed poses (position interpolated
// linearly, orientation by the constant-rate rotation between keys, i.e. slerp), or a
// constant twist. Evaluated on the haptic thread each tick: X_WO_at() and
// velocity_W() allocate nothing and never throw.

#include "geometry/pose.h"

#include <Eigen/Core>

#include <vector>

namespace mhd {

/// One key of a keyframed motion: the object's pose in the world at t_s.
struct PoseKey {
  double t_s = 0.0;
  Pose X_WO = Pose::Identity();
};

/// What a keyframed motion does after its last key.
enum class MotionRepeat {
  Hold,      ///< stays at the last key (and before the first, at the first)
  Loop,      ///< starts again from the first key; the last key must equal the first
  PingPong,  ///< plays backwards to the first key, then forwards again
};

class ObjectMotion {
 public:
  /// Keyframed motion. Throws std::invalid_argument (naming the key) unless there are at
  /// least two keys, times are finite and strictly increasing, poses finite and rigid,
  /// and, for Loop, the last pose equals the first (a loop must not teleport the object).
  [[nodiscard]] static ObjectMotion keyframes(std::vector<PoseKey> keys, MotionRepeat repeat);

  /// Constant twist from X_WO_0 at t = 0: the origin moves at v_W_mps, and the object
  /// turns at omega_W_radps about its own origin (both in the world frame).
  /// Throws std::invalid_argument unless everything is finite.
  [[nodiscard]] static ObjectMotion twist(const Pose& X_WO_0, const Eigen::Vector3d& v_W_mps,
                                          const Eigen::Vector3d& omega_W_radps);

  /// The object's pose at t_s (any finite t_s; a twist runs before t = 0 too).
  [[nodiscard]] Pose X_WO_at(double t_s) const noexcept;

  /// Velocity of the object's origin, and its angular velocity, at t_s (world frame). At a
  /// key, the segment that starts there.
  [[nodiscard]] Eigen::Vector3d v_W_origin_at(double t_s) const noexcept;
  [[nodiscard]] Eigen::Vector3d omega_W_at(double t_s) const noexcept;

  /// The highest speed of the origin and the highest rotation rate the motion ever has.
  [[nodiscard]] double max_speed_mps() const noexcept;
  [[nodiscard]] double max_rate_radps() const noexcept;

 private:
  // A segment between keys i and i+1 with its constant velocities.
  struct Segment {
    double t0_s = 0.0, t1_s = 0.0;
    Pose X_WO_0 = Pose::Identity();
    Eigen::Vector3d v_W_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d omega_W_radps = Eigen::Vector3d::Zero();
  };
  // Local time of the keyframed motion inside [t_first, t_last], and the direction it runs.
  struct LocalTime {
    double t_s = 0.0;
    double direction = 1.0;  ///< -1 playing backwards (PingPong), 0 held at an end
  };
  [[nodiscard]] LocalTime local_time(double t_s) const noexcept;
  [[nodiscard]] const Segment& segment_at(double t_local_s) const noexcept;
  [[nodiscard]] static Pose advance(const Segment& s, double dt_s) noexcept;

  std::vector<Segment> segments_;  // one for a twist, unbounded in time
  MotionRepeat repeat_ = MotionRepeat::Hold;
  bool is_twist_ = false;
};

}  // namespace mhd
