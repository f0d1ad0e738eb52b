// The sim_is900 tracker plugin: the C ABI over Is900Model. It measures the scene's
// simulated world (base pose and head; sim_world/sim_session.h), moving the scene's
// simulated user there first. The host advances it with simulate_until(); tracker_read
// returns what has arrived by then.

#include "sim_is900_model.h"
#include "sim_world/sim_session.h"
#include "world_truth.h"

#include <mhd/plugin_sdk.hpp>

#include <Eigen/Geometry>

#include <array>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>

namespace mhd::sim_is900 {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

/// R = Rz(yaw) Ry(pitch) Rx(roll), as the scene's rpy_deg.
Eigen::Quaterniond rotation_from_rpy_deg(const Eigen::Vector3d& rpy_deg) {
  const Eigen::Vector3d rpy = rpy_deg * kDegToRad;
  return Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX());
}

/// A pose given as a scene's <frame>: <prefix>_position_m (default 0 0 0), and
/// <prefix>_rpy_deg or <prefix>_quaternion_wxyz (not both; default unrotated). With none
/// of the three given, the fallback.
Eigen::Isometry3d read_pose(const sdk::Params& params, const std::string& prefix, const Eigen::Isometry3d& fallback) {
  const std::string rpy = prefix + "_rpy_deg";
  const std::string quaternion = prefix + "_quaternion_wxyz";
  const auto p = params.optional_vector3<Eigen::Vector3d>(prefix + "_position_m");
  const auto rpy_deg = params.optional_vector3<Eigen::Vector3d>(rpy);
  const auto q = params.optional_quaternion<Eigen::Quaterniond>(quaternion);
  if (rpy_deg && q) {
    throw sdk::ParamError("parameters '" + rpy + "' and '" + quaternion + "' exclude each other");
  }
  if (!p && !rpy_deg && !q) return fallback;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  if (p) X.translation() = *p;
  if (rpy_deg) X.linear() = rotation_from_rpy_deg(*rpy_deg).toRotationMatrix();
  if (q) X.linear() = q->toRotationMatrix();
  return X;
}

Is900Config read_config(const sdk::Params& params) {
  Is900Config c;
  c.rate_hz = params.number("rate_hz");
  c.latency_s = params.number("latency_s");
  c.position_sigma_m = params.number("position_sigma_m");
  c.angle_sigma_rad = params.number("angle_sigma_deg") * kDegToRad;
  c.base_sensor_id = static_cast<std::uint32_t>(params.integer("base_sensor_id"));
  c.head_sensor_id = static_cast<std::uint32_t>(params.integer("head_sensor_id"));
  c.X_BS = read_pose(params, "base_sensor", c.X_BS);
  c.X_WT = read_pose(params, "tracker", c.X_WT);
  c.buffer_capacity = static_cast<std::size_t>(params.integer("buffer_capacity"));
  c.seed = params.integer("seed");
  if (params.text("bystander") == "on") {
    Bystander other;
    other.head_sensor_id = static_cast<std::uint32_t>(params.integer("bystander_head_sensor_id"));
    other.base_sensor_id = static_cast<std::uint32_t>(params.integer("bystander_base_sensor_id"));
    other.p_W_head = params.optional_vector3<Eigen::Vector3d>("bystander_head_position_m").value_or(other.p_W_head);
    const Eigen::Vector3d base =
        params.optional_vector3<Eigen::Vector3d>("bystander_base_position_m").value_or(Eigen::Vector3d::Zero());
    other.base_x_m = base.x();
    other.base_z_m = base.z();
    c.bystander = other;
  }
  if (const auto sensor = params.optional_text("dropout_sensor")) {  // declared: one of the four
    if (*sensor == "head") c.dropout_sensor_id = c.head_sensor_id;
    if (*sensor == "base") c.dropout_sensor_id = c.base_sensor_id;
    if (sensor->starts_with("bystander_") && !c.bystander) {
      throw sdk::ParamError("parameter 'dropout_sensor' is '" + *sensor + "' but there is no bystander");
    }
    if (*sensor == "bystander_head") c.dropout_sensor_id = c.bystander->head_sensor_id;
    if (*sensor == "bystander_base") c.dropout_sensor_id = c.bystander->base_sensor_id;
  }
  c.dropout_start_s = params.number("dropout_start_s");
  c.dropout_duration_s = params.number("dropout_duration_s");
  if (c.base_sensor_id == c.head_sensor_id) {
    throw sdk::ParamError("parameters 'base_sensor_id' and 'head_sensor_id' must differ, both are " +
                          std::to_string(c.base_sensor_id));
  }
  return c;
}

}  // namespace

class SimIs900Plugin {
 public:
  static constexpr std::array kParams{
      sdk::number("rate_hz", "Hz", "180", "samples per second per sensor", sdk::between(1, 10000)),
      sdk::number("latency_s", "s", "0.004", "from measurement to delivery", sdk::between(0, 1)),
      sdk::number("position_sigma_m", "m", "0.0025", "position noise per axis (standard deviation)", sdk::between(0, 1)),
      sdk::number("angle_sigma_deg", "deg", "0.35", "orientation noise per axis (standard deviation)", sdk::between(0, 45)),
      sdk::integer("base_sensor_id", "", "0", "the base sensor's id", sdk::between(0, 4294967295.0)),
      sdk::integer("head_sensor_id", "", "1", "the head sensor's id (must differ from the base's)",
                   sdk::between(0, 4294967295.0)),
      sdk::vector3("base_sensor_position_m", "m", nullptr, "the base sensor in the base frame (default: pomhi.xml's)",
                    sdk::between(-10, 10)),
      sdk::vector3("base_sensor_rpy_deg", "deg", nullptr, "its roll, pitch, yaw (not with the quaternion)",
                   sdk::between(-360, 360)),
      sdk::quaternion("base_sensor_quaternion_wxyz", nullptr, "its orientation (not with rpy)"),
      sdk::vector3("tracker_position_m", "m", nullptr, "the tracker frame in the world (default: pomhi.xml's)",
                   sdk::between(-1000, 1000)),
      sdk::vector3("tracker_rpy_deg", "deg", nullptr, "its roll, pitch, yaw (not with the quaternion)",
                   sdk::between(-360, 360)),
      sdk::quaternion("tracker_quaternion_wxyz", nullptr, "its orientation (not with rpy)"),
      sdk::integer("buffer_capacity", "", "256", "samples kept between reads", sdk::between(1, 1048576)),
      sdk::integer("seed", "", "0", "noise seed", sdk::between(0, 4294967295.0)),
      sdk::choice("bystander", "off|on", "off", "another rig standing still on the floor, measured too"),
      sdk::integer("bystander_head_sensor_id", "", "2", "the bystander's sensor on its user's head",
                   sdk::between(0, 4294967295.0)),
      sdk::integer("bystander_base_sensor_id", "", "3", "and the one on its base", sdk::between(0, 4294967295.0)),
      sdk::vector3("bystander_head_position_m", "m", nullptr, "where its head is in the world (default: the origin)",
                   sdk::between(-1000, 1000)),
      sdk::vector3("bystander_base_position_m", "m", nullptr,
                   "where its base stands in the world, x 0 z (heading 0; default: the origin)", sdk::between(-1000, 1000)),
      sdk::choice("dropout_sensor", "head|base|bystander_head|bystander_base", nullptr,
                  "a sensor that stops reporting for a while"),
      sdk::number("dropout_start_s", "s", "0", "when the dropout starts, after start()", sdk::between(0, 86400)),
      sdk::number("dropout_duration_s", "s", "0", "how long it lasts", sdk::between(0, 86400)),
  };

  SimIs900Plugin(const mhd_host& host, const sdk::Params& params)
      : host_(host), session_(sim_world::SimSession::acquire(host)), model_(read_config(params)) {}

  void start() {
    const double now = sdk::host_now(host_);
    session_->advance_to(now);
    model_.start(now, world_truth(session_->world()));
  }
  std::size_t tracker_read(std::span<mhd_tracker_sample> out) { return model_.read(out); }
  /// Samples lost because the host read too seldom (the oldest makes room).
  std::size_t counters(std::span<mhd_counter> out) const {
    if (out.empty()) return 1;
    out[0] = {"dropped_buffer_full", model_.dropped()};
    return 1;
  }
  void simulate_until(double t_s) {
    session_->advance_to(t_s);
    model_.simulate_until(t_s, world_truth(session_->world()));
  }

 private:
  mhd_host host_;
  std::shared_ptr<sim_world::SimSession> session_;
  Is900Model model_;
};

}  // namespace mhd::sim_is900

MHD_PLUGIN_ENTRY(mhd::sim_is900::SimIs900Plugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Simulated IS-900: base and head sensors at 180 Hz with noise and 4 ms latency (and, "
                                 "optionally, a standing bystander rig's)"})
