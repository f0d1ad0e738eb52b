#pragma once
// The truth of a simulated session: the base's planar pose, the user's head pose and
// the user's hand. The simulated plugins of one scene share one world through their own
// support library (libs/sim_world/sim_session.h), never through the host, so the
// simulated tracker sees the base that the simulated base moves. World frame W: y up,
// floor at y = 0; a planar heading h is a rotation about +y_W, forward x = (cos h, 0,
// -sin h).
//
// Threads: the simulated device reads the base and the hand on the haptic thread, so
// every reader is lock-free (realtime::Seqlock: never locks, never allocates); writers
// (tracker, base and user at their own rates) are serialised by one writer mutex.

#include <Eigen/Geometry>

#include "realtime/seqlock.h"
#include "simulation_config/simulated_user_config.h"

#include <atomic>
#include <mutex>

namespace mhd::simulation {

struct HeadPose {
  Eigen::Vector3d p_W_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_W = Eigen::Quaterniond::Identity();
};

class SimulatedWorld {
 public:
  /// Base at the origin with heading 0, head and hand at the origin, head unrotated.
  SimulatedWorld();
  // Shared by reference between threads and plugins: never copied or moved.
  SimulatedWorld(const SimulatedWorld&) = delete;
  SimulatedWorld& operator=(const SimulatedWorld&) = delete;
  SimulatedWorld(SimulatedWorld&&) = delete;
  SimulatedWorld& operator=(SimulatedWorld&&) = delete;
  ~SimulatedWorld() = default;

  [[nodiscard]] PlanarPose base_pose() const noexcept;
  void set_base_pose(const PlanarPose& pose);

  /// The base's lift: the arm's height above the rig file's (0 on a base without one).
  [[nodiscard]] double lift_m() const noexcept { return lift_m_.read()[0]; }
  void set_lift_m(double lift_m);

  [[nodiscard]] HeadPose head() const noexcept;
  /// The quaternion is stored normalised.
  void set_head(const HeadPose& head);

  [[nodiscard]] Eigen::Vector3d hand() const noexcept;
  void set_hand(const Eigen::Vector3d& p_W_m);
  /// Whether anyone (a simulated user, a test) has placed the hand: until then a
  /// simulated device rests its hand where its own parameters say.
  [[nodiscard]] bool has_hand() const noexcept { return hand_placed_.load(std::memory_order_acquire); }

 private:
  std::mutex writer_mutex_;
  realtime::Seqlock<3> base_;      ///< x_m, z_m, heading_rad
  realtime::Seqlock<1> lift_m_;
  realtime::Seqlock<7> head_;      ///< p_W_m, then q_W as w, x, y, z
  realtime::Seqlock<3> hand_W_m_;
  std::atomic<bool> hand_placed_{false};
};

}  // namespace mhd::simulation
