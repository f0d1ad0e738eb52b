#include "dds_common/shared_sim_world.h"

#include <cmath>

namespace mhd::dds {

mhd_dds_SimWorld sim_world_sample(const mhd_sim_world& world, std::uint32_t rig_id, std::uint64_t sequence,
                                  std::int64_t timestamp_ns) {
  mhd_dds_SimWorld s{};
  s.rig_id = rig_id;
  s.sequence_number = sequence;
  s.timestamp_ns = timestamp_ns;
  world.get_base_pose(world.context, &s.base_x_m, &s.base_z_m, &s.base_heading_rad);
  world.get_head(world.context, s.p_W_head_m, s.q_W_head_wxyz);
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

void SimWorldPublisher::publish(const mhd_sim_world& world, std::int64_t timestamp_ns) {
  publisher_.write(sim_world_sample(world, rig_id_, sequence_++, timestamp_ns));
}

SimWorldSubscriber::SimWorldSubscriber(const Participant& participant, std::uint32_t rig_id)
    : rig_id_(rig_id), subscriber_(participant, rig_partition(rig_id), 16) {}

bool SimWorldSubscriber::apply_newest(const mhd_sim_world& world) {
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
  world.set_base_pose(world.context, newest_.base_x_m, newest_.base_z_m, newest_.base_heading_rad);
  world.set_head(world.context, newest_.p_W_head_m, newest_.q_W_head_wxyz);
  ++applied_;
  return true;
}

}  // namespace mhd::dds
