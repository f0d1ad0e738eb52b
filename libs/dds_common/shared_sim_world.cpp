#include "dds_common/shared_sim_world.h"

#include <cmath>

namespace mhd::dds {

mhd_dds_SimWorld sim_world_sample(const simulation::SimulatedWorld& world, std::uint32_t rig_id, std::uint64_t sequence,
                                  std::int64_t timestamp_ns) {
  mhd_dds_SimWorld s{};
  s.rig_id = rig_id;
  s.sequence_number = sequence;
  s.timestamp_ns = timestamp_ns;
  const simulation::PlanarPose base = world.base_pose();
  s.base_x_m = base.x_m;
  s.base_z_m = base.z_m;
  s.base_heading_rad = base.heading_rad;
  const simulation::HeadPose head = world.head();
  for (int i = 0; i < 3; ++i) s.p_W_head_m[i] = head.p_W_m[i];
  s.q_W_head_wxyz[0] = head.q_W.w();
  s.q_W_head_wxyz[1] = head.q_W.x();
  s.q_W_head_wxyz[2] = head.q_W.y();
  s.q_W_head_wxyz[3] = head.q_W.z();
  return s;
}

bool sim_world_sample_valid(const mhd_dds_SimWorld& s) {
  bool finite = std::isfinite(s.base_x_m) && std::isfinite(s.base_z_m) && std::isfinite(s.base_heading_rad);
  double norm2 = 0.0;
  for (const double v : s.p_W_head_m) finite = finite && std::isfinite(v);
  for (const double v : s.q_W_head_wxyz) {
    finite = finite && std::isfinite(v);
    norm2 += v * v;
  }
  return finite && norm2 >= 0.25 && norm2 <= 4.0;
}

SimWorldPublisher::SimWorldPublisher(const Participant& participant, std::uint32_t rig_id)
    : rig_id_(rig_id), publisher_(participant, rig_partition(rig_id)) {}

void SimWorldPublisher::publish(const simulation::SimulatedWorld& world, std::int64_t timestamp_ns) {
  publisher_.write(sim_world_sample(world, rig_id_, sequence_++, timestamp_ns));
}

SimWorldSubscriber::SimWorldSubscriber(const Participant& participant, std::uint32_t rig_id)
    : rig_id_(rig_id), subscriber_(participant, rig_partition(rig_id), 16) {}

bool SimWorldSubscriber::apply_newest(simulation::SimulatedWorld& world) {
  bool found = false;
  for (;;) {
    const std::span<const mhd_dds_SimWorld> taken = subscriber_.reader().take();
    for (const mhd_dds_SimWorld& s : taken) {
      if (s.rig_id != rig_id_ || !sim_world_sample_valid(s)) {
        ++rejected_;
      } else if (!found || s.timestamp_ns >= newest_.timestamp_ns) {
        newest_ = s;
        found = true;
      }
    }
    if (taken.size() < 16) break;
  }
  if (!found) return false;
  world.set_base_pose({newest_.base_x_m, newest_.base_z_m, newest_.base_heading_rad});
  const double* p = newest_.p_W_head_m;
  const double* q = newest_.q_W_head_wxyz;
  world.set_head({Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Quaterniond(q[0], q[1], q[2], q[3])});
  ++applied_;
  return true;
}

}  // namespace mhd::dds
