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

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

std::optional<double> parse_number(std::string_view s) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc{} || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

/// Shortest round-trip form: "1.5", not "1.500000".
std::string format(double v) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  return std::string(buffer.data(), result.ptr);
}

bool positive(double v) { return v > 0.0 && std::isfinite(v); }
bool non_negative(double v) { return v >= 0.0 && std::isfinite(v); }

double wrap(double angle_rad) { return std::remainder(angle_rad, kTwoPi); }

Eigen::Vector2d forward(double heading_rad) { return {std::cos(heading_rad), -std::sin(heading_rad)}; }
Eigen::Vector2d right(double heading_rad) { return {std::sin(heading_rad), std::cos(heading_rad)}; }
/// The heading whose forward direction is (dx, dz).
double heading_of(double dx, double dz) { return std::atan2(-dz, dx); }

void validate(const SimulatedUserConfig& c) {
  require(positive(c.max_speed_mps), "max_speed_mps must be positive");
  require(positive(c.max_turn_rate_radps), "max_turn_rate_radps must be positive");
  require(positive(c.step_s), "step_s must be positive");
  require(std::isfinite(c.start_time_s), "start_time_s must be finite");
  require(non_negative(c.walk_speed_min_mps) && c.walk_speed_min_mps <= c.walk_speed_max_mps &&
              c.walk_speed_max_mps <= c.max_speed_mps,
          "walking speeds must satisfy 0 <= walk_speed_min_mps <= walk_speed_max_mps <= max_speed_mps");
  require(non_negative(c.walk_turn_rate_max_radps) && c.walk_turn_rate_max_radps <= c.max_turn_rate_radps,
          "walk_turn_rate_max_radps must be in [0, max_turn_rate_radps]");
  require(positive(c.side_step_speed_max_mps) && c.side_step_speed_max_mps <= c.max_speed_mps,
          "side_step_speed_max_mps must be in (0, max_speed_mps]");
  require(non_negative(c.side_step_probability) && non_negative(c.stand_probability) &&
              c.side_step_probability + c.stand_probability <= 1.0,
          "side_step_probability and stand_probability must be >= 0 with a sum <= 1");
  require(positive(c.area_half_size_m), "area_half_size_m must be positive");
  require(std::isfinite(c.start.x_m) && std::isfinite(c.start.z_m) && std::isfinite(c.start.heading_rad),
          "start must be finite");
  require(positive(c.eye_height_m), "eye_height_m must be positive");
  require(non_negative(c.hand_reach_m) && positive(c.hand_height_m) && non_negative(c.hand_motion_amplitude_m),
          "hand_reach_m, hand_height_m and hand_motion_amplitude_m must be >= 0 (height > 0)");
  require(!c.gaze_target_W || c.gaze_target_W->allFinite(), "gaze_target_W must be finite");
  if (c.loop_path) {
    const bool moves = std::any_of(c.path.begin(), c.path.end(), [&](const Waypoint& w) {
      return w.x_m != c.path.front().x_m || w.z_m != c.path.front().z_m;
    });
    require(moves, "a looping path needs two different waypoints");
  }
  for (std::size_t i = 0; i < c.path.size(); ++i) {
    const Waypoint& w = c.path[i];
    const std::string name = "waypoint " + std::to_string(i + 1);
    require(std::isfinite(w.x_m) && std::isfinite(w.z_m) && std::isfinite(w.speed_mps), name + ": not finite");
    const bool walked_to = i > 0 || (c.loop_path && c.path.size() > 1);
    if (!walked_to) continue;
    require(w.speed_mps > 0.0, name + ": speed must be positive, got " + format(w.speed_mps));
    require(w.speed_mps <= c.max_speed_mps,
            name + ": speed " + format(w.speed_mps) + " m/s is above max_speed_mps " + format(c.max_speed_mps));
  }
}

}  // namespace

std::vector<Waypoint> parse_waypoints(std::string_view text) {
  std::vector<Waypoint> path;
  int index = 0;
  for (;;) {
    const std::size_t semicolon = text.find(';');
    const std::string_view item = trim(text.substr(0, semicolon));
    ++index;
    if (!item.empty() || semicolon != std::string_view::npos) {
      // Three numbers separated by blanks.
      std::array<double, 3> v{};
      std::string_view rest = item;
      bool ok = true;
      for (double& x : v) {
        rest = trim(rest);
        const std::size_t end = std::min(rest.find_first_of(" \t"), rest.size());
        const auto number = parse_number(rest.substr(0, end));
        ok = ok && number.has_value();
        x = number.value_or(0.0);
        rest = rest.substr(end);
      }
      if (!ok || !trim(rest).empty()) {
        throw std::invalid_argument("waypoint " + std::to_string(index) + ": expected 'x z speed_mps', got '" +
                                    std::string(item) + "'");
      }
      path.push_back({v[0], v[1], v[2]});
    }
    if (semicolon == std::string_view::npos) break;
    text.remove_prefix(semicolon + 1);
    if (trim(text).empty()) break;  // a trailing ';'
  }
  if (path.empty()) throw std::invalid_argument("no waypoints");
  return path;
}

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
  h.p_W_m = Eigen::Vector3d(b.x_m, config_.eye_height_m, b.z_m);
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
  Eigen::Vector3d p(b.x_m + reach.x(), config_.hand_height_m, b.z_m + reach.y());
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
