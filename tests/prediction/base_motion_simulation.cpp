#include "base_motion_simulation.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace mhd::test {

namespace {

struct Sample {
  double t_measured_s;
  double t_arrival_s;
  BasePose pose;
};

Eigen::Vector2d position(const BasePose& p) { return Eigen::Vector2d(p.x_m, p.z_m); }

// The scored point `lever` metres ahead of the base centre, along B's x axis.
Eigen::Vector2d point_ahead(const BasePose& p, double lever_m) {
  return position(p) + lever_m * Eigen::Vector2d(std::cos(p.heading_rad), -std::sin(p.heading_rad));
}

class LeapMeter {
 public:
  void add(const Eigen::Vector2d& output, const Eigen::Vector2d& truth, bool scored) {
    if (has_previous_ && scored) {
      const double leap = ((output - previous_output_) - (truth - previous_truth_)).norm();
      const double error = (output - truth).norm();
      figures_.max_leap_m = std::max(figures_.max_leap_m, leap);
      figures_.max_error_m = std::max(figures_.max_error_m, error);
      sum_leap2_ += leap * leap;
      sum_error2_ += error * error;
      ++count_;
    }
    previous_output_ = output;
    previous_truth_ = truth;
    has_previous_ = true;
  }
  LeapFigures figures() const {
    LeapFigures f = figures_;
    if (count_ > 0) {
      f.rms_leap_m = std::sqrt(sum_leap2_ / static_cast<double>(count_));
      f.rms_error_m = std::sqrt(sum_error2_ / static_cast<double>(count_));
    }
    return f;
  }

 private:
  LeapFigures figures_;
  bool has_previous_ = false;
  Eigen::Vector2d previous_output_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d previous_truth_ = Eigen::Vector2d::Zero();
  double sum_leap2_ = 0, sum_error2_ = 0;
  long count_ = 0;
};

std::string mm(const LeapFigures& f) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "leap max %.4f rms %.4f mm, error max %.3f rms %.3f mm", f.max_leap_m * 1e3,
                f.rms_leap_m * 1e3, f.max_error_m * 1e3, f.rms_error_m * 1e3);
  return buffer;
}

}  // namespace

std::string BaseMotionResult::summary() const {
  return "predicted base:  " + mm(predicted_base) + "\npredicted point: " + mm(predicted_point) +
         "\nheld base:       " + mm(held_base) + "\nheld point:      " + mm(held_point) +
         "\nsamples " + std::to_string(samples_sent) + ", ignored " + std::to_string(samples_ignored) + ", resets " +
         std::to_string(resets);
}

BasePose true_base_pose(const BaseMotionScenario& scenario, double t_s) {
  return integrate_twist(scenario.start, scenario.twist_B, t_s);
}

BaseMotionResult run_base_motion(const BaseMotionScenario& scenario, const BasePosePredictorSettings& settings) {
  std::mt19937_64 rng(scenario.seed);
  std::normal_distribution<double> position_noise(0.0, scenario.position_noise_m);
  std::normal_distribution<double> heading_noise(0.0, scenario.heading_noise_rad);
  std::uniform_real_distribution<double> unit(0.0, 1.0);

  std::vector<Sample> samples;
  const long sample_count = std::lround(scenario.duration_s / scenario.sample_period_s);
  for (long k = 0; k < sample_count; ++k) {
    const double t = static_cast<double>(k) * scenario.sample_period_s;
    if (unit(rng) < scenario.drop_probability) continue;
    const BasePose truth = true_base_pose(scenario, t);
    Sample s{t, t + scenario.latency_s + scenario.arrival_jitter_s * unit(rng),
             BasePose{truth.x_m + position_noise(rng), truth.z_m + position_noise(rng),
                      wrap_angle(truth.heading_rad + heading_noise(rng))}};
    if (unit(rng) < scenario.late_probability) s.t_arrival_s += 1.5 * scenario.sample_period_s;
    samples.push_back(s);
  }
  std::stable_sort(samples.begin(), samples.end(),
                   [](const Sample& a, const Sample& b) { return a.t_arrival_s < b.t_arrival_s; });

  BasePosePredictor predictor(settings);
  BaseMotionResult result;
  LeapMeter predicted_base, predicted_point, held_base, held_point;
  std::size_t next_sample = 0;
  double next_command_s = 0.0;
  bool has_held = false;
  Sample held{};
  const long ticks = std::lround(scenario.duration_s / scenario.tick_s);
  for (long i = 0; i <= ticks; ++i) {
    const double t = static_cast<double>(i) * scenario.tick_s;
    if (scenario.send_commands && t >= next_command_s) {
      predictor.add_command(t, scenario.twist_B);
      next_command_s += 0.1;
    }
    for (; next_sample < samples.size() && samples[next_sample].t_arrival_s <= t; ++next_sample) {
      const Sample& s = samples[next_sample];
      ++result.samples_sent;
      predictor.add_measurement(s.t_measured_s, s.pose);
      if (!has_held || s.t_measured_s > held.t_measured_s) held = s;
      has_held = true;
    }
    if (!has_held) continue;
    const bool scored = t >= scenario.warmup_s;
    const BasePose truth = true_base_pose(scenario, t);
    const BasePose out = predictor.predict(t);
    predicted_base.add(position(out), position(truth), scored);
    predicted_point.add(point_ahead(out, scenario.lever_m), point_ahead(truth, scenario.lever_m), scored);
    held_base.add(position(held.pose), position(truth), scored);
    held_point.add(point_ahead(held.pose, scenario.lever_m), point_ahead(truth, scenario.lever_m), scored);
  }
  result.predicted_base = predicted_base.figures();
  result.predicted_point = predicted_point.figures();
  result.held_base = held_base.figures();
  result.held_point = held_point.figures();
  result.samples_ignored = predictor.ignored_count();
  result.resets = predictor.reset_count();
  return result;
}

}  // namespace mhd::test
