#include "haptic_server/recording_replay.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhd {
namespace {

Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

std::array<double, 3> arr(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// |a - b|, with two NaNs in the same place counting as equal and one NaN as infinite.
double difference(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i) {
    const bool na = std::isnan(a[i]), nb = std::isnan(b[i]);
    if (na && nb) continue;
    if (na || nb) return std::numeric_limits<double>::infinity();
    d = std::max(d, std::abs(a[i] - b[i]));
  }
  return d;
}

}  // namespace

ReplayComparison replay_recording(const CompiledScene& scene, const Rig& rig, const HapticTickSettings& settings,
                              const std::vector<RecordingRow>& rows) {
  ReplayComparison result;
  HapticTick tick(scene, rig, settings);
  result.replayed.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RecordingRow& in = rows[i];
    std::optional<BasePose> base;
    double age_s = HapticTick::kNoTracker;  // a desktop rig: fixed base, no tracker
    if (rig.kind() == RigKind::Desktop) {
      base = BasePose{};
    } else {
      if (in.tracker_age_s >= 0.0) base = BasePose{in.base_x_m, in.base_z_m, in.base_heading_rad};
      age_s = in.tracker_age_s >= 0.0 ? in.tracker_age_s : std::numeric_limits<double>::infinity();
    }
    tick.set_lift_m(in.lift_m);
    const HapticTickOutput out = tick.render(in.t_s, in.dt_s, vec(in.p_D_tool_m), base, age_s);

    RecordingRow r = in;
    r.p_W_hip = arr(out.p_W_hip);
    r.proxy_W_m = arr(out.proxy_W_m);
    r.force_W_N = arr(out.force_W_N);
    r.cmd_force_W_N = arr(out.proxy_force_W_N);
    r.force_D_N = arr(out.force_D_N);
    r.safety_gain = out.safety_gain;
    r.contact = out.in_contact ? 1 : 0;
    r.contact_object = out.contact_object;
    result.replayed.push_back(r);

    const double df = difference(out.force_W_N, vec(in.force_W_N));
    const double dp = difference(out.proxy_W_m, vec(in.proxy_W_m));
    const double dt = difference(out.force_D_N, vec(in.force_D_N));
    result.max_force_difference_N = std::max(result.max_force_difference_N, df);
    result.max_proxy_difference_m = std::max(result.max_proxy_difference_m, dp);
    result.max_device_force_difference_N = std::max(result.max_device_force_difference_N, dt);
    if (df > 0.0 || dp > 0.0 || dt > 0.0) {
      if (result.differing_rows == 0) result.first_differing_row = i;
      ++result.differing_rows;
    }
    ++result.rows;
  }
  return result;
}

}  // namespace mhd
