#include "geometry/object_motion.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd {
namespace {

bool finite_rigid(const Pose& X) {
  if (!X.matrix().allFinite()) return false;
  const Eigen::Matrix3d R = X.linear();
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9 && R.determinant() > 0.0;
}

std::string key_name(std::size_t i) { return "motion key " + std::to_string(i + 1); }

}  // namespace

ObjectMotion ObjectMotion::keyframes(std::vector<PoseKey> keys, MotionRepeat repeat) {
  if (keys.size() < 2) throw std::invalid_argument("a keyframed motion needs at least two keys");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (!std::isfinite(keys[i].t_s)) throw std::invalid_argument(key_name(i) + ": time is not finite");
    if (!finite_rigid(keys[i].X_WO)) throw std::invalid_argument(key_name(i) + ": pose is not a finite rigid pose");
    if (i > 0 && !(keys[i].t_s > keys[i - 1].t_s)) {
      throw std::invalid_argument(key_name(i) + ": time must be later than the key before");
    }
  }
  ObjectMotion m;
  m.repeat_ = repeat;
  m.segments_.reserve(keys.size() - 1);
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    Segment s;
    s.t0_s = keys[i].t_s;
    s.t1_s = keys[i + 1].t_s;
    s.X_WO_0 = keys[i].X_WO;
    const double dt_s = s.t1_s - s.t0_s;
    s.v_W_mps = (keys[i + 1].X_WO.translation() - keys[i].X_WO.translation()) / dt_s;
    const Eigen::AngleAxisd turn(Eigen::Matrix3d(keys[i + 1].X_WO.linear() * keys[i].X_WO.linear().transpose()));
    // Near 180 degrees the axis of the shortest turn is undefined: the author must say.
    if (turn.angle() > std::numbers::pi - 1e-6) {
      throw std::invalid_argument(key_name(i + 1) + ": turns 180 degrees or more from the key before (add a key between)");
    }
    s.omega_W_radps = turn.axis() * (turn.angle() / dt_s);
    m.segments_.push_back(s);
  }
  if (repeat == MotionRepeat::Loop) {
    const Pose& first = keys.front().X_WO;
    const Pose& last = keys.back().X_WO;
    if ((first.matrix() - last.matrix()).cwiseAbs().maxCoeff() > 1e-9) {
      throw std::invalid_argument(key_name(keys.size() - 1) +
                                  ": a looping motion must end at the pose it starts from (or use pingpong)");
    }
  }
  return m;
}

ObjectMotion ObjectMotion::twist(const Pose& X_WO_0, const Eigen::Vector3d& v_W_mps,
                                 const Eigen::Vector3d& omega_W_radps) {
  if (!finite_rigid(X_WO_0) || !v_W_mps.allFinite() || !omega_W_radps.allFinite()) {
    throw std::invalid_argument("a twist motion needs a finite pose, velocity and angular velocity");
  }
  ObjectMotion m;
  m.is_twist_ = true;
  Segment s;
  s.X_WO_0 = X_WO_0;
  s.v_W_mps = v_W_mps;
  s.omega_W_radps = omega_W_radps;
  m.segments_.push_back(s);
  return m;
}

ObjectMotion::LocalTime ObjectMotion::local_time(double t_s) const noexcept {
  if (is_twist_) return {t_s, 1.0};
  const double first = segments_.front().t0_s;
  const double last = segments_.back().t1_s;
  const double period = last - first;
  switch (repeat_) {
    case MotionRepeat::Hold:
      if (t_s <= first) return {first, 0.0};
      if (t_s >= last) return {last, 0.0};
      return {t_s, 1.0};
    case MotionRepeat::Loop: {
      double u = std::fmod(t_s - first, period);
      if (u < 0.0) u += period;
      return {first + u, 1.0};
    }
    case MotionRepeat::PingPong: {
      double u = std::fmod(t_s - first, 2.0 * period);
      if (u < 0.0) u += 2.0 * period;
      if (u <= period) return {first + u, 1.0};
      return {first + 2.0 * period - u, -1.0};
    }
  }
  return {first, 0.0};
}

const ObjectMotion::Segment& ObjectMotion::segment_at(double t_local_s) const noexcept {
  if (is_twist_) return segments_.front();
  const auto it = std::upper_bound(segments_.begin(), segments_.end(), t_local_s,
                                   [](double t, const Segment& s) { return t < s.t1_s; });
  return it == segments_.end() ? segments_.back() : *it;
}

Pose ObjectMotion::advance(const Segment& s, double dt_s) noexcept {
  Pose X = s.X_WO_0;
  X.translation() += s.v_W_mps * dt_s;
  const double rate = s.omega_W_radps.norm();
  if (rate > 0.0) {
    X.linear() = Eigen::AngleAxisd(rate * dt_s, s.omega_W_radps / rate).toRotationMatrix() * s.X_WO_0.linear();
  }
  return X;
}

Pose ObjectMotion::X_WO_at(double t_s) const noexcept {
  const LocalTime local = local_time(t_s);
  const Segment& s = segment_at(local.t_s);
  return advance(s, local.t_s - s.t0_s);
}

Eigen::Vector3d ObjectMotion::v_W_origin_at(double t_s) const noexcept {
  const LocalTime local = local_time(t_s);
  return local.direction * segment_at(local.t_s).v_W_mps;
}

Eigen::Vector3d ObjectMotion::omega_W_at(double t_s) const noexcept {
  const LocalTime local = local_time(t_s);
  return local.direction * segment_at(local.t_s).omega_W_radps;
}

double ObjectMotion::max_speed_mps() const noexcept {
  double v = 0.0;
  for (const Segment& s : segments_) v = std::max(v, s.v_W_mps.norm());
  return v;
}

double ObjectMotion::max_rate_radps() const noexcept {
  double w = 0.0;
  for (const Segment& s : segments_) w = std::max(w, s.omega_W_radps.norm());
  return w;
}

}  // namespace mhd
