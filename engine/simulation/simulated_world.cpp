#include "simulation/simulated_world.h"

namespace mhd::simulation {
namespace {

SimulatedWorld& world_of(void* context) { return *static_cast<SimulatedWorld*>(context); }

void table_get_base_pose(void* context, double* x_m, double* z_m, double* heading_rad) {
  const PlanarPose p = world_of(context).base_pose();
  *x_m = p.x_m;
  *z_m = p.z_m;
  *heading_rad = p.heading_rad;
}

void table_set_base_pose(void* context, double x_m, double z_m, double heading_rad) {
  world_of(context).set_base_pose({x_m, z_m, heading_rad});
}

void table_get_hand(void* context, double p_W_m[3]) {
  const Eigen::Vector3d p = world_of(context).hand();
  for (int i = 0; i < 3; ++i) p_W_m[i] = p[i];
}

void table_set_hand(void* context, const double p_W_m[3]) {
  world_of(context).set_hand(Eigen::Vector3d(p_W_m[0], p_W_m[1], p_W_m[2]));
}

void table_get_head(void* context, double p_W_m[3], double q_W_wxyz[4]) {
  const HeadPose h = world_of(context).head();
  for (int i = 0; i < 3; ++i) p_W_m[i] = h.p_W_m[i];
  q_W_wxyz[0] = h.q_W.w();
  q_W_wxyz[1] = h.q_W.x();
  q_W_wxyz[2] = h.q_W.y();
  q_W_wxyz[3] = h.q_W.z();
}

void table_set_head(void* context, const double p_W_m[3], const double q_W_wxyz[4]) {
  world_of(context).set_head(
      {Eigen::Vector3d(p_W_m[0], p_W_m[1], p_W_m[2]), Eigen::Quaterniond(q_W_wxyz[0], q_W_wxyz[1], q_W_wxyz[2], q_W_wxyz[3])});
}

}  // namespace

SimulatedWorld::SimulatedWorld() {
  for (auto& c : hand_W_m_) c.store(0.0, std::memory_order_relaxed);
  table_.context = this;
  table_.get_base_pose = &table_get_base_pose;
  table_.set_base_pose = &table_set_base_pose;
  table_.get_hand = &table_get_hand;
  table_.set_hand = &table_set_hand;
  table_.get_head = &table_get_head;
  table_.set_head = &table_set_head;
}

PlanarPose SimulatedWorld::base_pose() const {
  const std::lock_guard lock(mutex_);
  return base_;
}

void SimulatedWorld::set_base_pose(const PlanarPose& pose) {
  const std::lock_guard lock(mutex_);
  base_ = pose;
}

HeadPose SimulatedWorld::head() const {
  const std::lock_guard lock(mutex_);
  return head_;
}

void SimulatedWorld::set_head(const HeadPose& head) {
  const std::lock_guard lock(mutex_);
  head_ = head;
  head_.q_W.normalize();
}

// Seqlock without standalone fences (which ThreadSanitizer cannot check): a reader that
// acquires a value a writer released also sees that writer's odd sequence number, so its
// second look at the sequence catches any write it overlapped.
Eigen::Vector3d SimulatedWorld::hand() const noexcept {
  Eigen::Vector3d p;
  for (;;) {
    const std::uint64_t before = hand_sequence_.load(std::memory_order_acquire);
    if ((before & 1u) != 0) continue;  // a write is under way
    for (int i = 0; i < 3; ++i) p[i] = hand_W_m_[static_cast<std::size_t>(i)].load(std::memory_order_acquire);
    if (hand_sequence_.load(std::memory_order_relaxed) == before) return p;
  }
}

void SimulatedWorld::set_hand(const Eigen::Vector3d& p_W_m) {
  const std::lock_guard lock(hand_writer_mutex_);
  const std::uint64_t sequence = hand_sequence_.load(std::memory_order_relaxed);
  hand_sequence_.store(sequence + 1, std::memory_order_relaxed);
  for (int i = 0; i < 3; ++i) hand_W_m_[static_cast<std::size_t>(i)].store(p_W_m[i], std::memory_order_release);
  hand_sequence_.store(sequence + 2, std::memory_order_release);
}

}  // namespace mhd::simulation
