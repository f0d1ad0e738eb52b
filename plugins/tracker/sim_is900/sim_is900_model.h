#pragma once
// An InterSense IS-900 with two sensors: one on the mobile base, one on the user's
// head. 180 Hz, Gaussian noise (2-3 mm, 0.25-0.5 deg), 4 ms latency.
//
// Measurement k is taken at t_k = t_start + k / rate_hz for both sensors; its
// timestamp is t_k and it becomes readable at t_k + latency_s. The truth at t_k is
// interpolated between the two world states the model was given around t_k (linear
// in position and heading, slerp for the head), so calling simulate_until() less often
// than 180 Hz blurs motion but does not drop measurements.
//
// Output frame: poses are X_T_sensor in the tracker frame T, X_T_S = X_WT^-1 X_WS with
// X_WT the tracker's pose in the world. Frames: world y-up; the base frame B is on the
// floor under the robot, x_B forward, y_B up, z_B = x_B x y_B, X_WB = [Ry(h), (x, 0, z)].
// The defaults of X_WT and X_BS are the thesis rig of scenes/rigs/pomhi.xml.

#include <mhd/plugin_abi.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <vector>

namespace mhd::sim_is900 {

/// What the tracker measures, at one instant (world frame).
struct WorldTruth {
  double base_x_m = 0.0;
  double base_z_m = 0.0;
  double base_heading_rad = 0.0;
  Eigen::Vector3d p_W_head = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_W_head = Eigen::Quaterniond::Identity();
};

/// Another rig on the same floor, standing still: its user's head and its base, measured
/// like the rig's own sensors (a shared floor's tracking, in a one-process simulation).
struct Bystander {
  std::uint32_t head_sensor_id = 2;
  std::uint32_t base_sensor_id = 3;
  Eigen::Vector3d p_W_head = Eigen::Vector3d::Zero();
  double base_x_m = 0.0;
  double base_z_m = 0.0;
};

struct Is900Config {
  double rate_hz = 180.0;
  double latency_s = 0.004;
  double position_sigma_m = 0.0025;             ///< per axis
  double angle_sigma_rad = 0.006108652381980153;  ///< 0.35 deg, per axis of a small rotation
  std::uint32_t base_sensor_id = 0;
  std::uint32_t head_sensor_id = 1;
  /// The base sensor's pose in the base frame: pomhi.xml's (X_base_sensor_robot
  /// X_robot_base)^-1, 1.1808 m up and 0.206 m to the left, its z axis up.
  Eigen::Isometry3d X_BS = Eigen::Translation3d(0.0, 1.1808, -0.206) * Eigen::Quaterniond(0.5, -0.5, -0.5, -0.5);
  /// The tracker frame's pose in the world: pomhi.xml's is900 frame (thesis eq. 4.1),
  /// 2.624 m up with z pointing down.
  Eigen::Isometry3d X_WT = Eigen::Translation3d(0.0, 2.624, 0.0) * Eigen::Quaterniond(0.5, 0.5, 0.5, -0.5);
  /// Samples held until read; when full, the oldest is dropped (and counted).
  std::size_t buffer_capacity = 256;
  std::optional<Bystander> bystander;
  /// A dropout: the sensor with this id (none: no dropout) is not measured from
  /// dropout_start_s after start for dropout_duration_s (no samples, no sequence numbers).
  std::optional<std::uint32_t> dropout_sensor_id;
  double dropout_start_s = 0.0;
  double dropout_duration_s = 0.0;
  std::uint64_t seed = 0;
};

/// Not thread-safe.
class Is900Model {
 public:
  /// Throws std::invalid_argument for a bad setting (equal sensor ids, capacity 0, ...).
  explicit Is900Model(const Is900Config& config);

  /// Puts the first measurement at t_s, with the world as it is then. Empties the
  /// buffer; sequence numbers keep counting across restarts.
  void start(double t_s, const WorldTruth& truth);

  /// Takes every measurement due up to t_s, the world being `truth` at t_s.
  /// No-op if t_s is not ahead. Precondition: started.
  void simulate_until(double t_s, const WorldTruth& truth);

  /// Moves the samples readable at the current time (timestamp + latency <= time_s())
  /// into out, oldest first; returns how many.
  std::size_t read(std::span<mhd_tracker_sample> out);

  [[nodiscard]] double time_s() const { return time_s_; }
  /// Samples measured and not yet read (readable or still in flight).
  [[nodiscard]] std::size_t buffered() const { return size_; }
  /// Samples lost to a full buffer since construction.
  [[nodiscard]] std::uint64_t dropped() const { return dropped_; }
  [[nodiscard]] const Is900Config& config() const { return config_; }

 private:
  void measure(double t_s, const WorldTruth& truth);
  /// True when `sensor_id` is inside its dropout window at host time t_s.
  [[nodiscard]] bool dropped_out(std::uint32_t sensor_id, double t_s) const;
  void push(std::uint32_t sensor_id, std::uint64_t& sequence, double t_s, const Eigen::Isometry3d& X_TS);

  Is900Config config_;
  Eigen::Isometry3d X_TW_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};

  bool started_ = false;
  double t0_s_ = 0.0;
  std::int64_t next_k_ = 0;
  double time_s_ = 0.0;
  WorldTruth truth_;  ///< the world at time_s_
  std::uint64_t base_sequence_ = 0;
  std::uint64_t head_sequence_ = 0;
  std::uint64_t bystander_head_sequence_ = 0;
  std::uint64_t bystander_base_sequence_ = 0;

  std::vector<mhd_tracker_sample> ring_;
  std::size_t oldest_ = 0;
  std::size_t size_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace mhd::sim_is900
