#include "simulation/simulated_user.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace mhd::simulation {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double wrap(double angle_rad) { return std::remainder(angle_rad, kTwoPi); }

Eigen::Vector2d forward(double heading_rad) { return {std::cos(heading_rad), -std::sin(heading_rad)}; }
Eigen::Vector2d right(double heading_rad) { return {std::sin(heading_rad), std::cos(heading_rad)}; }
/// The heading whose forward direction is (dx, dz).
double heading_of(double dx, double dz) { return std::atan2(-dz, dx); }

}  // namespace

SimulatedUser::SimulatedUser(SimulatedUserConfig config) : config_(std::move(config)), rng_(config_.seed) {
  validate(config_);
  for (int i = 0; i < 3; ++i) {
    hand_frequency_hz_[i] = uniform(0.2, 0.6);
    hand_phase_rad_[i] = uniform(0.0, kTwoPi);
  }
  GridState s;
  if (config_.path.empty()) {
    s = {config_.start.x_m, config_.start.z_m, wrap(config_.start.heading_rad), false};
    manoeuvre_end_s_ = config_.start_time_s;
  } else {
    const Waypoint& first = config_.path.front();
    s = {first.x_m, first.z_m, wrap(config_.start.heading_rad), false};
    if (config_.path.size() > 1) {
      const Waypoint& second = config_.path[1];
      if (second.x_m != first.x_m || second.z_m != first.z_m) {
        s.heading_rad = heading_of(second.x_m - first.x_m, second.z_m - first.z_m);
      }
    } else {
      path_finished_ = true;
    }
  }
  previous_ = s;
  time_s_ = config_.start_time_s;
  next_ = step(previous_, time_s_);
}

double SimulatedUser::uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

void SimulatedUser::advance_to(double t_s) {
  if (std::isnan(t_s)) throw std::invalid_argument("SimulatedUser::advance_to: time is NaN");
  if (t_s <= time_s_) return;
  const double t0 = config_.start_time_s;
  const double dt = config_.step_s;
  while (t_s >= t0 + static_cast<double>(step_index_ + 1) * dt) {
    previous_ = next_;
    ++step_index_;
    next_ = step(previous_, t0 + static_cast<double>(step_index_) * dt);
  }
  time_s_ = t_s;
}

void SimulatedUser::update(double t_s, SimulatedWorld& world) {
  advance_to(t_s);
  world.set_head(head());
  world.set_hand(hand_W());
}

PlanarPose SimulatedUser::body() const {
  const double t_n = config_.start_time_s + static_cast<double>(step_index_) * config_.step_s;
  const double alpha = std::clamp((time_s_ - t_n) / config_.step_s, 0.0, 1.0);
  return {previous_.x_m + alpha * (next_.x_m - previous_.x_m), previous_.z_m + alpha * (next_.z_m - previous_.z_m),
          wrap(previous_.heading_rad + alpha * wrap(next_.heading_rad - previous_.heading_rad))};
}

Eigen::Vector2d SimulatedUser::velocity_W() const {
  return Eigen::Vector2d(next_.x_m - previous_.x_m, next_.z_m - previous_.z_m) / config_.step_s;
}

HeadPose SimulatedUser::head() const {
  const PlanarPose b = body();
  HeadPose h;
  const double eye_height_m =
      config_.hand_height_sweep
          ? eye_height_at(config_.eye_height_m, hand_height_at(config_.hand_height_sweep, config_.hand_height_m,
                                                               time_s_ - config_.start_time_s))
          : config_.eye_height_m;
  h.p_W_m = Eigen::Vector3d(b.x_m, eye_height_m, b.z_m);
  double yaw = b.heading_rad;
  double pitch = 0.0;
  if (config_.gaze_target_W) {
    const Eigen::Vector3d d = *config_.gaze_target_W - h.p_W_m;
    const double horizontal = std::hypot(d.x(), d.z());
    if (horizontal > 0.0) yaw = heading_of(d.x(), d.z());
    if (horizontal > 0.0 || d.y() != 0.0) pitch = std::atan2(d.y(), horizontal);
  }
  // Head frame: x the line of sight, y up, z to the right; pitch turns x towards +y.
  h.q_W = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitZ());
  return h;
}

Eigen::Vector3d SimulatedUser::hand_W() const {
  const PlanarPose b = body();
  const Eigen::Vector2d reach = config_.hand_reach_m * forward(b.heading_rad);
  const double height_m =
      hand_height_at(config_.hand_height_sweep, config_.hand_height_m, time_s_ - config_.start_time_s);
  Eigen::Vector3d p(b.x_m + reach.x(), height_m, b.z_m + reach.y());
  for (int i = 0; i < 3; ++i) {
    p[i] += config_.hand_motion_amplitude_m * std::sin(kTwoPi * hand_frequency_hz_[i] * time_s_ + hand_phase_rad_[i]);
  }
  return p;
}

SimulatedUser::GridState SimulatedUser::step(const GridState& s, double t_s) {
  return config_.path.empty() ? step_random(s, t_s) : step_path(s);
}

SimulatedUser::GridState SimulatedUser::step_path(const GridState& s) {
  GridState out = s;
  double time_left_s = config_.step_s;  // a waypoint reached mid-step lends the rest to the next leg
  double dx = 0.0;
  double dz = 0.0;
  while (!path_finished_ && time_left_s > 0.0) {
    const Waypoint& target = config_.path[target_];
    dx = target.x_m - out.x_m;
    dz = target.z_m - out.z_m;
    const double distance = std::hypot(dx, dz);
    const double stride = target.speed_mps * time_left_s;
    if (distance > stride) {
      out.x_m += dx / distance * stride;
      out.z_m += dz / distance * stride;
      break;
    }
    out.x_m = target.x_m;
    out.z_m = target.z_m;
    time_left_s -= distance / target.speed_mps;
    if (target_ + 1 < config_.path.size()) {
      ++target_;
    } else if (config_.loop_path) {
      target_ = 0;
    } else {
      path_finished_ = true;
    }
  }
  if (dx != 0.0 || dz != 0.0) {  // turn towards the leg walked last
    const double max_turn = config_.max_turn_rate_radps * config_.step_s;
    out.heading_rad = wrap(s.heading_rad + std::clamp(wrap(heading_of(dx, dz) - s.heading_rad), -max_turn, max_turn));
  }
  return out;
}

void SimulatedUser::choose_manoeuvre(const GridState& s, double t_s) {
  const double r = uniform(0.0, 1.0);
  double duration_s = 0.0;
  if (r < config_.side_step_probability) {
    manoeuvre_ = Manoeuvre::SideStep;
    duration_s = uniform(0.25, 0.6);
    speed_mps_ = uniform(0.5, 1.0) * config_.side_step_speed_max_mps;
    const bool to_the_right = uniform(0.0, 1.0) < 0.5;
    const Eigen::Vector2d p(s.x_m, s.z_m);
    if (p.cwiseAbs().maxCoeff() > 0.5 * config_.area_half_size_m) {
      // Far out: step towards the middle.
      if (right(s.heading_rad).dot(-p) < 0.0) speed_mps_ = -speed_mps_;
    } else if (!to_the_right) {
      speed_mps_ = -speed_mps_;
    }
    ++side_steps_started_;
  } else if (r < config_.side_step_probability + config_.stand_probability) {
    manoeuvre_ = Manoeuvre::Stand;
    duration_s = uniform(0.5, 1.5);
  } else {
    manoeuvre_ = Manoeuvre::Walk;
    duration_s = uniform(1.0, 3.0);
    speed_mps_ = uniform(config_.walk_speed_min_mps, config_.walk_speed_max_mps);
    turn_rate_radps_ = uniform(-config_.walk_turn_rate_max_radps, config_.walk_turn_rate_max_radps);
  }
  manoeuvre_end_s_ = t_s + duration_s;
}

SimulatedUser::GridState SimulatedUser::step_random(const GridState& s, double t_s) {
  if (t_s >= manoeuvre_end_s_) choose_manoeuvre(s, t_s);
  GridState out = s;
  out.side_stepping = manoeuvre_ == Manoeuvre::SideStep;
  const double dt = config_.step_s;
  switch (manoeuvre_) {
    case Manoeuvre::Walk: {
      double rate = turn_rate_radps_;
      const double a = config_.area_half_size_m;
      if (std::abs(s.x_m) > a || std::abs(s.z_m) > a) {  // outside: steer back towards the origin
        const double turn = wrap(heading_of(-s.x_m, -s.z_m) - s.heading_rad);
        rate = std::clamp(turn / dt, -config_.max_turn_rate_radps, config_.max_turn_rate_radps);
      }
      out.heading_rad = wrap(s.heading_rad + rate * dt);
      const Eigen::Vector2d d = speed_mps_ * dt * forward(out.heading_rad);
      out.x_m += d.x();
      out.z_m += d.y();
      break;
    }
    case Manoeuvre::SideStep: {
      const Eigen::Vector2d d = speed_mps_ * dt * right(s.heading_rad);
      out.x_m += d.x();
      out.z_m += d.y();
      break;
    }
    case Manoeuvre::Stand: break;
  }
  return out;
}

}  // namespace mhd::simulation
