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

SimulatedWorld::SimulatedWorld() : head_({0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0}) {
  table_.context = this;
  table_.get_base_pose = &table_get_base_pose;
  table_.set_base_pose = &table_set_base_pose;
  table_.get_hand = &table_get_hand;
  table_.set_hand = &table_set_hand;
  table_.get_head = &table_get_head;
  table_.set_head = &table_set_head;
}

PlanarPose SimulatedWorld::base_pose() const noexcept {
  const auto v = base_.read();
  return {v[0], v[1], v[2]};
}

void SimulatedWorld::set_base_pose(const PlanarPose& pose) {
  const std::lock_guard lock(writer_mutex_);
  base_.write({pose.x_m, pose.z_m, pose.heading_rad});
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
}

}  // namespace mhd::simulation
