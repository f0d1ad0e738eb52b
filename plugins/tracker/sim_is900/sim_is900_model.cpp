#include "sim_is900_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mhd::sim_is900 {
namespace {

constexpr double kTimeTolerance_s = 1e-9;

void require(bool ok, const char* message) {
  if (!ok) throw std::invalid_argument(message);
}

WorldTruth interpolate(const WorldTruth& a, const WorldTruth& b, double alpha) {
  WorldTruth out;
  out.base_x_m = a.base_x_m + alpha * (b.base_x_m - a.base_x_m);
  out.base_z_m = a.base_z_m + alpha * (b.base_z_m - a.base_z_m);
  const double turn = std::remainder(b.base_heading_rad - a.base_heading_rad, 2.0 * std::numbers::pi);
  out.base_heading_rad = a.base_heading_rad + alpha * turn;
  out.p_W_head = a.p_W_head + alpha * (b.p_W_head - a.p_W_head);
  out.q_W_head = a.q_W_head.slerp(alpha, b.q_W_head);
  return out;
}

Eigen::Isometry3d base_pose_W(const WorldTruth& truth) {
  Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
  X_WB.linear() = Eigen::AngleAxisd(truth.base_heading_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  X_WB.translation() << truth.base_x_m, 0.0, truth.base_z_m;
  return X_WB;
}

bool finite(const WorldTruth& t) {
  return std::isfinite(t.base_x_m) && std::isfinite(t.base_z_m) && std::isfinite(t.base_heading_rad) &&
         t.p_W_head.allFinite() && t.q_W_head.coeffs().allFinite() && t.q_W_head.norm() > 0.0;
}

}  // namespace

Is900Model::Is900Model(const Is900Config& config)
    : config_(config), X_TW_(config.X_WT.inverse(Eigen::Isometry)), rng_(config.seed) {
  require(config.rate_hz > 0.0 && std::isfinite(config.rate_hz), "rate_hz must be a positive number");
  require(config.latency_s >= 0.0 && std::isfinite(config.latency_s), "latency_s must be a non-negative number");
  require(config.position_sigma_m >= 0.0 && std::isfinite(config.position_sigma_m),
          "position_sigma_m must be a non-negative number");
  require(config.angle_sigma_rad >= 0.0 && std::isfinite(config.angle_sigma_rad),
          "angle_sigma must be a non-negative number");
  require(config.base_sensor_id != config.head_sensor_id, "the base and head sensors need different ids");
  require(config.buffer_capacity > 0, "buffer_capacity must be at least 1");
  require(config.dropout_start_s >= 0.0 && std::isfinite(config.dropout_start_s),
          "dropout_start_s must be a non-negative number");
  require(config.dropout_duration_s >= 0.0 && std::isfinite(config.dropout_duration_s),
          "dropout_duration_s must be a non-negative number");
  require(config.X_BS.matrix().allFinite() && config.X_WT.matrix().allFinite(), "sensor and tracker poses must be finite");
  if (const auto& other = config.bystander) {
    const std::uint32_t ids[] = {config.base_sensor_id, config.head_sensor_id, other->head_sensor_id,
                                 other->base_sensor_id};
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) require(ids[i] != ids[j], "the four sensors (base, head, the bystander's head "
                                                                 "and base) need different ids");
    require(other->p_W_head.allFinite() && std::isfinite(other->base_x_m) && std::isfinite(other->base_z_m),
            "the bystander's positions must be finite");
  }
  ring_.resize(config.buffer_capacity);
}

void Is900Model::start(double t_s, const WorldTruth& truth) {
  require(std::isfinite(t_s), "start time must be finite");
  require(finite(truth), "the world state is not finite");
  started_ = true;
  t0_s_ = t_s;
  next_k_ = 0;
  time_s_ = t_s;
  truth_ = truth;
  truth_.q_W_head.normalize();
  oldest_ = 0;
  size_ = 0;
}

void Is900Model::simulate_until(double t_s, const WorldTruth& truth) {
  if (!started_) throw std::logic_error("simulate_until before start");
  require(std::isfinite(t_s), "simulation time must be finite");
  require(finite(truth), "the world state is not finite");
  WorldTruth now = truth;
  now.q_W_head.normalize();
  if (t_s < time_s_) return;
  const double span_s = t_s - time_s_;
  for (;;) {
    const double t_k = t0_s_ + static_cast<double>(next_k_) / config_.rate_hz;
    if (t_k > t_s + kTimeTolerance_s) break;
    const double alpha = span_s > 0.0 ? std::clamp((t_k - time_s_) / span_s, 0.0, 1.0) : 1.0;
    measure(t_k, interpolate(truth_, now, alpha));
    ++next_k_;
  }
  time_s_ = t_s;
  truth_ = now;
}

void Is900Model::measure(double t_s, const WorldTruth& truth) {
  const Eigen::Isometry3d X_WS = base_pose_W(truth) * config_.X_BS;
  Eigen::Isometry3d X_WH = Eigen::Isometry3d::Identity();
  X_WH.linear() = truth.q_W_head.toRotationMatrix();
  X_WH.translation() = truth.p_W_head;
  if (!dropped_out(config_.base_sensor_id, t_s)) push(config_.base_sensor_id, base_sequence_, t_s, X_TW_ * X_WS);
  if (!dropped_out(config_.head_sensor_id, t_s)) push(config_.head_sensor_id, head_sequence_, t_s, X_TW_ * X_WH);
  if (!config_.bystander) return;
  const Bystander& other = *config_.bystander;
  WorldTruth other_base;
  other_base.base_x_m = other.base_x_m;
  other_base.base_z_m = other.base_z_m;
  const Eigen::Isometry3d X_WS_other = base_pose_W(other_base) * config_.X_BS;
  Eigen::Isometry3d X_WH_other = Eigen::Isometry3d::Identity();
  X_WH_other.translation() = other.p_W_head;
  if (!dropped_out(other.base_sensor_id, t_s))
    push(other.base_sensor_id, bystander_base_sequence_, t_s, X_TW_ * X_WS_other);
  if (!dropped_out(other.head_sensor_id, t_s))
    push(other.head_sensor_id, bystander_head_sequence_, t_s, X_TW_ * X_WH_other);
}

bool Is900Model::dropped_out(std::uint32_t sensor_id, double t_s) const {
  if (config_.dropout_sensor_id != sensor_id) return false;
  const double since_start_s = t_s - t0_s_;
  return since_start_s >= config_.dropout_start_s - kTimeTolerance_s &&
         since_start_s < config_.dropout_start_s + config_.dropout_duration_s - kTimeTolerance_s;
}

void Is900Model::push(std::uint32_t sensor_id, std::uint64_t& sequence, double t_s, const Eigen::Isometry3d& X_TS) {
  const Eigen::Vector3d position_noise(unit_normal_(rng_), unit_normal_(rng_), unit_normal_(rng_));
  const Eigen::Vector3d angle_noise(unit_normal_(rng_), unit_normal_(rng_), unit_normal_(rng_));
  const Eigen::Vector3d p_T = X_TS.translation() + config_.position_sigma_m * position_noise;
  const Eigen::Vector3d rotation_vector = config_.angle_sigma_rad * angle_noise;
  const double angle = rotation_vector.norm();
  Eigen::Quaterniond q_T(X_TS.linear());
  if (angle > 0.0) q_T = Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation_vector / angle)) * q_T;
  q_T.normalize();
  if (q_T.w() < 0.0) q_T.coeffs() = -q_T.coeffs();  // one sign per rotation: w >= 0

  mhd_tracker_sample sample{};
  sample.sensor_id = sensor_id;
  sample.sequence = sequence++;
  sample.timestamp_s = t_s;
  for (int i = 0; i < 3; ++i) sample.p_T_m[i] = p_T[i];
  sample.q_T_wxyz[0] = q_T.w();
  sample.q_T_wxyz[1] = q_T.x();
  sample.q_T_wxyz[2] = q_T.y();
  sample.q_T_wxyz[3] = q_T.z();

  const std::size_t capacity = ring_.size();
  if (size_ == capacity) {  // full: the oldest makes room
    oldest_ = (oldest_ + 1) % capacity;
    --size_;
    ++dropped_;
  }
  ring_[(oldest_ + size_) % capacity] = sample;
  ++size_;
}

std::size_t Is900Model::read(std::span<mhd_tracker_sample> out) {
  std::size_t n = 0;
  while (n < out.size() && size_ > 0) {
    const mhd_tracker_sample& oldest = ring_[oldest_];
    if (oldest.timestamp_s + config_.latency_s > time_s_ + kTimeTolerance_s) break;  // still in flight
    out[n++] = oldest;
    oldest_ = (oldest_ + 1) % ring_.size();
    --size_;
  }
  return n;
}

}  // namespace mhd::sim_is900
