#include "simulation/simulated_world.h"

namespace mhd::simulation {
SimulatedWorld::SimulatedWorld() : head_({0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0}) {}

PlanarPose SimulatedWorld::base_pose() const noexcept {
  const auto v = base_.read();
  return {v[0], v[1], v[2]};
}

void SimulatedWorld::set_base_pose(const PlanarPose& pose) {
  const std::lock_guard lock(writer_mutex_);
  base_.write({pose.x_m, pose.z_m, pose.heading_rad});
}

void SimulatedWorld::set_lift_m(double lift_m) {
  const std::lock_guard lock(writer_mutex_);
  lift_m_.write({lift_m});
}

HeadPose SimulatedWorld::head() const noexcept {
  const auto v = head_.read();
  return {Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Quaterniond(v[3], v[4], v[5], v[6])};
}

void SimulatedWorld::set_head(const HeadPose& head) {
  const Eigen::Quaterniond q = head.q_W.normalized();
  const std::lock_guard lock(writer_mutex_);
  head_.write({head.p_W_m.x(), head.p_W_m.y(), head.p_W_m.z(), q.w(), q.x(), q.y(), q.z()});
}

Eigen::Vector3d SimulatedWorld::hand() const noexcept {
  const auto v = hand_W_m_.read();
  return {v[0], v[1], v[2]};
}

void SimulatedWorld::set_hand(const Eigen::Vector3d& p_W_m) {
  const std::lock_guard lock(writer_mutex_);
  hand_W_m_.write({p_W_m.x(), p_W_m.y(), p_W_m.z()});
  hand_placed_.store(true, std::memory_order_release);
}

}  // namespace mhd::simulation
