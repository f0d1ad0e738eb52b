#include "dds_common/dds_convert.h"

#include <algorithm>
#include <cmath>

namespace mhd::dds {

std::int64_t realtime_from_host(double t_s, double host_now_s, std::int64_t now_ns) {
  return now_ns - std::llround((host_now_s - t_s) * 1e9);
}

double host_from_realtime(std::int64_t t_ns, double host_now_s, std::int64_t now_ns) {
  return host_now_s - static_cast<double>(now_ns - t_ns) * 1e-9;
}

mhd_dds_TrackerSample to_dds(const mhd_tracker_sample& s, std::uint32_t rig_id, std::int64_t timestamp_ns) {
  mhd_dds_TrackerSample d{};
  d.rig_id = rig_id;
  d.sensor_id = s.sensor_id;
  d.sequence_number = s.sequence;
  d.timestamp_ns = timestamp_ns;
  std::copy_n(s.p_T_m, 3, d.p_T_m);
  std::copy_n(s.q_T_wxyz, 4, d.q_T_wxyz);
  return d;
}

mhd_tracker_sample from_dds(const mhd_dds_TrackerSample& s, double timestamp_s) {
  mhd_tracker_sample d{};
  d.sensor_id = s.sensor_id;
  d.sequence = s.sequence_number;
  d.timestamp_s = timestamp_s;
  std::copy_n(s.p_T_m, 3, d.p_T_m);
  std::copy_n(s.q_T_wxyz, 4, d.q_T_wxyz);
  return d;
}

mhd_dds_RigState to_dds(const mhd_display_frame& f, std::uint32_t rig_id, std::uint64_t sequence,
                        std::int64_t timestamp_ns) {
  mhd_dds_RigState d{};
  d.rig_id = rig_id;
  d.sequence_number = sequence;
  d.timestamp_ns = timestamp_ns;
  std::copy_n(f.p_W_hip_m, 3, d.p_W_hip_m);
  std::copy_n(f.p_W_proxy_m, 3, d.p_W_proxy_m);
  std::copy_n(f.force_W_N, 3, d.force_W_N);
  d.in_contact = f.in_contact != 0;
  d.base_x_m = f.base_x_m;
  d.base_z_m = f.base_z_m;
  d.base_heading_rad = f.base_heading_rad;
  std::copy_n(f.p_W_head_m, 3, d.p_W_head_m);
  std::copy_n(f.q_W_head_wxyz, 4, d.q_W_head_wxyz);
  return d;
}

mhd_display_frame from_dds(const mhd_dds_RigState& s, double timestamp_s) {
  mhd_display_frame f{};
  f.timestamp_s = timestamp_s;
  std::copy_n(s.p_W_hip_m, 3, f.p_W_hip_m);
  std::copy_n(s.p_W_proxy_m, 3, f.p_W_proxy_m);
  std::copy_n(s.force_W_N, 3, f.force_W_N);
  f.in_contact = s.in_contact ? 1 : 0;
  f.base_x_m = s.base_x_m;
  f.base_z_m = s.base_z_m;
  f.base_heading_rad = s.base_heading_rad;
  std::copy_n(s.p_W_head_m, 3, f.p_W_head_m);
  std::copy_n(s.q_W_head_wxyz, 4, f.q_W_head_wxyz);
  return f;
}

}  // namespace mhd::dds
