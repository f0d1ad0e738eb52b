#pragma once
// The truth of a simulated session: the base's planar pose, the user's head pose and
// the user's hand, shared by the simulated plugins through the ABI's mhd_sim_world
// table (table()), so the simulated tracker sees the base that the simulated base
// moves. World frame W: y up, floor at y = 0; a planar heading h is a rotation about
// +y_W, forward x = (cos h, 0, -sin h).
//
// Threads: base and head sit behind a small mutex; they are read and written at
// tracker and base rates (<= a few hundred Hz) and the haptic thread must not touch
// them. The hand is read by the simulated device at 1 kHz, so it is a seqlock:
// hand() never locks and never allocates (it retries while a write is under way);
// set_hand() writers are serialised by their own mutex.

#include <mhd/plugin_abi.h>

#include <Eigen/Geometry>

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>

namespace mhd::simulation {

/// A pose on the floor: position (x, z) and heading about +y.
struct PlanarPose {
  double x_m = 0.0;
  double z_m = 0.0;
  double heading_rad = 0.0;
};

struct HeadPose {
  Eigen::Vector3d p_W_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_W = Eigen::Quaterniond::Identity();
};

class SimulatedWorld {
 public:
  /// Base at the origin with heading 0, head and hand at the origin, head unrotated.
  SimulatedWorld();
  // table() points at this object.
  SimulatedWorld(const SimulatedWorld&) = delete;
  SimulatedWorld& operator=(const SimulatedWorld&) = delete;
  SimulatedWorld(SimulatedWorld&&) = delete;
  SimulatedWorld& operator=(SimulatedWorld&&) = delete;
  ~SimulatedWorld() = default;

  [[nodiscard]] PlanarPose base_pose() const;
  void set_base_pose(const PlanarPose& pose);

  [[nodiscard]] HeadPose head() const;
  /// The quaternion is stored normalised.
  void set_head(const HeadPose& head);

  /// Lock-free; safe on the haptic thread.
  [[nodiscard]] Eigen::Vector3d hand() const noexcept;
  void set_hand(const Eigen::Vector3d& p_W_m);

  /// The C table for mhd_host::sim_world; valid while this object lives.
  [[nodiscard]] const mhd_sim_world& table() const noexcept { return table_; }

 private:
  mutable std::mutex mutex_;
  PlanarPose base_;
  HeadPose head_;

  std::mutex hand_writer_mutex_;
  std::atomic<std::uint64_t> hand_sequence_{0};  ///< odd while a write is under way
  std::array<std::atomic<double>, 3> hand_W_m_{};
  static_assert(std::atomic<double>::is_always_lock_free && std::atomic<std::uint64_t>::is_always_lock_free);

  mhd_sim_world table_{};
};

}  // namespace mhd::simulation
