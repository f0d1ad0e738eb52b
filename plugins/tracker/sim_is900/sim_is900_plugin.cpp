// The sim_is900 tracker plugin: the C ABI over Is900Model. It measures the shared
// simulated world (base pose and head), so it needs the host's sim_world. The host
// advances it with simulate_until(); tracker_read returns what has arrived by then.

#include "sim_is900_model.h"
#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include <mhd/plugin_abi.h>
#include <mhd/plugin_params.hpp>

#include <array>
#include <atomic>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <string>

namespace mhd::sim_is900 {
namespace {

using plugin_support::guarded_open;

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
Eigen::Isometry3d read_pose(plugin_support::ParamReader& reader, const std::string& prefix,
                            const Eigen::Isometry3d& fallback) {
  const std::string rpy = prefix + "_rpy_deg";
  const std::string quaternion = prefix + "_quaternion_wxyz";
  const auto p = reader.optional_vector3((prefix + "_position_m").c_str());
  const auto rpy_deg = reader.optional_vector3(rpy.c_str());
  const auto q = reader.optional_quaternion(quaternion.c_str());
  if (rpy_deg && q) {
    throw plugin_support::ParamError("parameters '" + rpy + "' and '" + quaternion + "' exclude each other");
  }
  if (!p && !rpy_deg && !q) return fallback;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  if (p) X.translation() = *p;
  if (rpy_deg) X.linear() = rotation_from_rpy_deg(*rpy_deg).toRotationMatrix();
  if (q) X.linear() = q->toRotationMatrix();
  return X;
}

WorldTruth read_world(const mhd_sim_world& world) {
  WorldTruth t;
  world.get_base_pose(world.context, &t.base_x_m, &t.base_z_m, &t.base_heading_rad);
  double p[3];
  double q[4];
  world.get_head(world.context, p, q);
  t.p_W_head = Eigen::Vector3d(p[0], p[1], p[2]);
  t.q_W_head = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  return t;
}

struct Instance {
  Instance(const mhd_host& h, const Is900Config& config) : host(h), model(config) {}

  std::atomic<bool> in_call{false};  ///< plugin_support::with_instance's
  mhd_host host;
  Is900Model model;
  bool started = false;
};

constexpr std::array kParams{
    sdk::number("rate_hz", "Hz", "180", "samples per second per sensor", sdk::positive()),
    sdk::number("latency_s", "s", "0.004", "from measurement to delivery", sdk::non_negative()),
    sdk::number("position_sigma_m", "m", "0.0025", "position noise per axis (standard deviation)", sdk::non_negative()),
    sdk::number("angle_sigma_deg", "deg", "0.35", "orientation noise per axis (standard deviation)", sdk::non_negative()),
    sdk::integer("base_sensor_id", "", "0", "the base sensor's id", sdk::between(0, 4294967295.0)),
    sdk::integer("head_sensor_id", "", "1", "the head sensor's id (must differ from the base's)",
                 sdk::between(0, 4294967295.0)),
    sdk::vector3("base_sensor_position_m", "m", nullptr, "the base sensor in the base frame (default: pomhi.xml's)"),
    sdk::vector3("base_sensor_rpy_deg", "deg", nullptr, "its roll, pitch, yaw (not with the quaternion)"),
    sdk::quaternion("base_sensor_quaternion_wxyz", nullptr, "its orientation (not with rpy)"),
    sdk::vector3("tracker_position_m", "m", nullptr, "the tracker frame in the world (default: pomhi.xml's)"),
    sdk::vector3("tracker_rpy_deg", "deg", nullptr, "its roll, pitch, yaw (not with the quaternion)"),
    sdk::quaternion("tracker_quaternion_wxyz", nullptr, "its orientation (not with rpy)"),
    sdk::integer("buffer_capacity", "", "256", "samples kept between reads", sdk::between(1, 1048576)),
    sdk::integer("seed", "", "0", "noise seed"),
    sdk::choice("dropout_sensor", "head|base", nullptr, "a sensor that stops reporting for a while"),
    sdk::number("dropout_start_s", "s", "0", "when the dropout starts, after start()", sdk::non_negative()),
    sdk::number("dropout_duration_s", "s", "0", "how long it lasts", sdk::non_negative()),
};

Is900Config read_config(const mhd_param* params, std::size_t count) {
  plugin_support::ParamReader reader(kParams, params, count);
  Is900Config c;
  c.rate_hz = reader.positive("rate_hz", c.rate_hz);
  c.latency_s = reader.non_negative("latency_s", c.latency_s);
  c.position_sigma_m = reader.non_negative("position_sigma_m", c.position_sigma_m);
  c.angle_sigma_rad = reader.non_negative("angle_sigma_deg", c.angle_sigma_rad / kDegToRad) * kDegToRad;
  c.base_sensor_id = static_cast<std::uint32_t>(reader.unsigned_integer("base_sensor_id", c.base_sensor_id, UINT32_MAX));
  c.head_sensor_id = static_cast<std::uint32_t>(reader.unsigned_integer("head_sensor_id", c.head_sensor_id, UINT32_MAX));
  c.X_BS = read_pose(reader, "base_sensor", c.X_BS);
  c.X_WT = read_pose(reader, "tracker", c.X_WT);
  c.buffer_capacity = static_cast<std::size_t>(reader.unsigned_integer("buffer_capacity", c.buffer_capacity, 1u << 20));
  c.seed = reader.unsigned_integer("seed", c.seed, UINT64_MAX);
  if (const auto sensor = reader.optional_text("dropout_sensor")) {
    if (*sensor != "head" && *sensor != "base") {
      throw plugin_support::ParamError("parameter 'dropout_sensor' must be 'head' or 'base', got '" + *sensor + "'");
    }
    c.dropout_sensor_id = *sensor == "head" ? c.head_sensor_id : c.base_sensor_id;
  }
  c.dropout_start_s = reader.non_negative("dropout_start_s", c.dropout_start_s);
  c.dropout_duration_s = reader.non_negative("dropout_duration_s", c.dropout_duration_s);
  reader.reject_unknown();
  if (c.buffer_capacity == 0) throw plugin_support::ParamError("parameter 'buffer_capacity' must be at least 1, got '0'");
  if (c.base_sensor_id == c.head_sensor_id) {
    throw plugin_support::ParamError("parameters 'base_sensor_id' and 'head_sensor_id' must differ, both are " +
                                     std::to_string(c.base_sensor_id));
  }
  return c;
}

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err) {
  return guarded_open(err, [&] {
    plugin_support::check_host(host);
    plugin_support::check_sim_world(*host);
    const Is900Config config = read_config(params, param_count);
    if (host->sim_world == nullptr) {
      throw std::runtime_error("sim_is900 measures the simulated world, but the host gives none (sim_world is NULL)");
    }
    return reinterpret_cast<mhd_plugin_instance*>(new Instance(*host, config));
  });
}

// Every instance call: find, lock and (for Need::Running) check the instance.
template <class F>
mhd_status call(mhd_plugin_instance* self, plugin_support::Need need, mhd_error* err, F&& f) {
  return plugin_support::with_instance<Instance>(MHD_PLUGIN_NAME, self, need, err, std::forward<F>(f));
}

mhd_status start_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    s.model.start(plugin_support::host_now(s.host), read_world(*s.host.sim_world));
    s.started = true;
    return MHD_OK;
  });
}

mhd_status stop_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    s.started = false;
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) { delete reinterpret_cast<Instance*>(self); }

mhd_status tracker_read(mhd_plugin_instance* self, mhd_tracker_sample* out, size_t capacity, size_t* count,
                        mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (count == nullptr || (out == nullptr && capacity > 0)) throw std::invalid_argument("tracker_read: NULL output");
    *count = s.model.read(std::span(out, capacity));
    return *count > 0 ? MHD_OK : MHD_NO_DATA;
  });
}

mhd_status simulate_until(mhd_plugin_instance* self, double t_s, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    s.model.simulate_until(t_s, read_world(*s.host.sim_world));
    return MHD_OK;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,
    .version = "1.0.0",
    .description = "Simulated IS-900: base and head sensors at 180 Hz with noise and 4 ms latency",
    .open = open_instance,
    .start = start_instance,
    .stop = stop_instance,
    .close = close_instance,
    .params = kParams.data(),
    .param_count = kParams.size(),
    .device_info = nullptr,
    .device_read = nullptr,
    .device_write = nullptr,
    .tracker_read = tracker_read,
    .base_read = nullptr,
    .base_write = nullptr,
    .display_write = nullptr,
    .simulate_until = simulate_until,
    .tracker_wait = nullptr,
    .counters = nullptr,
};

}  // namespace
}  // namespace mhd::sim_is900

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::sim_is900::kApi : nullptr;
}
