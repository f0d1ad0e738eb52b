#include "stress/stress_motion.h"

#include "stress/stroke_random.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mhd::stress {
namespace {

// Index drawn with the given weights.
int draw_weighted(std::mt19937_64& rng, std::initializer_list<double> weights) {
  double total = 0.0;
  for (const double w : weights) total += std::max(0.0, w);
  double u = verify::uniform01(rng) * total;
  int i = 0;
  for (const double w : weights) {
    if (u < std::max(0.0, w)) return i;
    u -= std::max(0.0, w);
    ++i;
  }
  return i - 1;
}

// Keys of a keyframed motion: the start, then `inner` poses displaced and turned about the
// centre, then (loop) the start again; each segment timed so that neither the origin's
// speed nor the rotation rate passes speed_mps / rate_radps.
std::vector<PoseKey> draw_keys(std::mt19937_64& rng, const Pose& X_WO_0, const Eigen::Vector3d& p_W_centre,
                               const MotionDrawParams& p, double speed_mps, double rate_radps, bool loop) {
  const int inner = 1 + static_cast<int>(verify::uniform01(rng) * 3.0);  // 1 to 3
  // A motion that may not translate turns about the origin, which then stays put.
  const Eigen::Vector3d pivot_W = speed_mps > 0.0 ? p_W_centre : Eigen::Vector3d(X_WO_0.translation());
  std::vector<Pose> poses{X_WO_0};
  for (int i = 0; i < inner; ++i) {
    const double excursion_m = speed_mps > 0.0 ? uniform_in(rng, 0.0, p.max_excursion_m) : 0.0;
    const double turn_rad = rate_radps > 0.0 ? uniform_in(rng, 0.0, p.max_key_turn_rad) : 0.0;
    const Eigen::Vector3d d_W = excursion_m * random_unit(rng);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(turn_rad, random_unit(rng)).toRotationMatrix();
    Pose X = Pose::Identity();
    X.linear() = R * X_WO_0.linear();
    X.translation() = pivot_W + d_W + R * (X_WO_0.translation() - pivot_W);
    poses.push_back(X);
  }
  if (loop) poses.push_back(X_WO_0);
  std::vector<PoseKey> keys;
  double t_s = 0.0;
  keys.push_back(PoseKey{t_s, poses.front()});
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const double move_m = (poses[i].translation() - poses[i - 1].translation()).norm();
    const double turn_rad = Eigen::AngleAxisd(poses[i].linear() * poses[i - 1].linear().transpose()).angle();
    double dt_s = 0.05;  // a key at most 20 per second: a jerk, not a blur
    if (move_m > 0.0) dt_s = std::max(dt_s, move_m / speed_mps);
    if (turn_rad > 0.0) dt_s = std::max(dt_s, turn_rad / rate_radps);
    t_s += dt_s;
    keys.push_back(PoseKey{t_s, poses[i]});
  }
  return keys;
}

}  // namespace

std::string_view to_string(MotionKind kind) {
  switch (kind) {
    case MotionKind::Twist: return "twist";
    case MotionKind::Loop: return "loop";
    case MotionKind::PingPong: return "pingpong";
  }
  return "?";
}

std::string_view to_string(StrokeAnchor anchor) {
  switch (anchor) {
    case StrokeAnchor::Riding: return "riding";
    case StrokeAnchor::Lagging: return "lagging";
    case StrokeAnchor::Still: return "still";
  }
  return "?";
}

double StressMotion::anchor_time_s(double t_s) const noexcept {
  switch (anchor) {
    case StrokeAnchor::Riding: return t_s;
    case StrokeAnchor::Lagging: return std::max(0.0, t_s - lag_s);
    case StrokeAnchor::Still: return 0.0;
  }
  return 0.0;
}

StressMotion draw_stress_motion(std::uint64_t seed, std::uint64_t object_key, std::size_t chain_first,
                                const Pose& X_WO_0, const Eigen::Vector3d& p_W_centre, const MotionDrawParams& params) {
  // Its own stream (salted), so the strokes' streams are not disturbed.
  std::mt19937_64 rng(splitmix64(seed ^ splitmix64(object_key ^ splitmix64(static_cast<std::uint64_t>(chain_first) ^
                                                                             0x6d6f74696f6eULL))));
  StressMotion m;
  m.kind = static_cast<MotionKind>(draw_weighted(rng, {params.weight_twist, params.weight_loop, params.weight_pingpong}));
  m.anchor = static_cast<StrokeAnchor>(
      draw_weighted(rng, {params.weight_riding, params.weight_lagging, params.weight_still}));
  m.lag_s = m.anchor == StrokeAnchor::Lagging ? uniform_in(rng, 0.0, params.max_lag_s) : 0.0;
  const bool full = verify::uniform01(rng) < params.full_speed_fraction;
  const double speed_mps = full ? params.max_speed_mps : uniform_in(rng, 0.05, 1.0) * params.max_speed_mps;
  const double rate_radps = full ? params.max_rate_radps : uniform_in(rng, 0.05, 1.0) * params.max_rate_radps;
  if (m.kind == MotionKind::Twist) {
    m.motion = ObjectMotion::twist(X_WO_0, speed_mps * random_unit(rng), rate_radps * random_unit(rng));
  } else {
    const bool loop = m.kind == MotionKind::Loop;
    m.motion = ObjectMotion::keyframes(draw_keys(rng, X_WO_0, p_W_centre, params, speed_mps, rate_radps, loop),
                                       loop ? MotionRepeat::Loop : MotionRepeat::PingPong);
  }
  return m;
}

}  // namespace mhd::stress
