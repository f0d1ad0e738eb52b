// A tracker for the fault-injection suite: the simulated IS-900 (sim_is900's Is900Model,
// measuring the host's simulated base and head) with delivery faults on top. The
// timestamps stay true (when the pose was measured); what the faults change is whether
// and when a sample arrives:
//   silent_after_s (never), resume_after_s (never)   nothing measured in between
//                                                    (seconds after start): a tracker
//                                                    that stops, and maybe comes back
//   loss (0)          each sample is lost with this probability
//   delay_ms (0), jitter_ms (0)   extra delivery delay delay_ms + U(-jitter_ms, +jitter_ms),
//                                 never below 0; samples stay in order, so a late one
//                                 holds back the next ones (they arrive bunched)
//   rate_hz (180), latency_s (0.004), position_sigma_m (0.0025), angle_sigma_deg (0.35),
//   seed (1)          the IS-900 model and the faults' random numbers
//   with_head (true)  also deliver the head sensor (id 1); the base sensor is id 0. The
//                     base guard moves the base only on fresh head data, so a tracker
//                     without it holds the base still
//   head_p_W_m ("x y z")  at start, stand the simulated user's head here (the world
//                         starts it at the origin, inside the base's keep-out)
//   delivery_log=<path>  at close, one line per delivered sample:
//                        "timestamp_s arrival_s sequence sensor_id"
#include "probe_common.h"

#include "sim_is900_model.h"

#include <algorithm>
#include <array>
#include <deque>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>

namespace {

struct Pending {
  mhd_tracker_sample sample;
  double arrival_s;
};

struct Tracker {
  explicit Tracker(const mhd::sim_is900::Is900Config& c) : model(c), rng(c.seed ^ 0x5eedu) {}
  const mhd_host* host = nullptr;
  mhd::sim_is900::Is900Model model;
  std::mt19937_64 rng;
  double silent_after_s = std::numeric_limits<double>::infinity();
  double resume_after_s = std::numeric_limits<double>::infinity();
  double loss = 0.0;
  double delay_s = 0.0;
  double jitter_s = 0.0;
  bool with_head = false;
  double t_start_s = 0.0;
  double last_arrival_s = -std::numeric_limits<double>::infinity();
  std::deque<Pending> in_flight;
  probe::Log delivered;
};

Tracker* of(mhd_plugin_instance* self) { return reinterpret_cast<Tracker*>(self); }

mhd::sim_is900::WorldTruth truth_of(const mhd_sim_world& w) {
  mhd::sim_is900::WorldTruth t;
  w.get_base_pose(w.context, &t.base_x_m, &t.base_z_m, &t.base_heading_rad);
  double p[3], q[4];
  w.get_head(w.context, p, q);
  t.p_W_head = Eigen::Vector3d(p[0], p[1], p[2]);
  t.q_W_head = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  return t;
}

mhd_plugin_instance* open_tracker(const mhd_host* host, const mhd_param* params, size_t count, mhd_error* err) {
  return probe::guarded_open(err, [&] {
    if (host->sim_world == nullptr) throw std::runtime_error("fi_tracker measures the simulated world: the host has none");
    mhd::sim_is900::Is900Config c;
    c.seed = 1;
    double silent = std::numeric_limits<double>::infinity(), resume = std::numeric_limits<double>::infinity();
    double loss = 0.0, delay_ms = 0.0, jitter_ms = 0.0;
    bool with_head = true;
    std::optional<std::array<double, 3>> head_p_W_m;
    std::string log;
    for (size_t i = 0; i < count; ++i) {
      const std::string name = params[i].name, value = params[i].value;
      if (name == "silent_after_s") silent = probe::number(name, value);
      else if (name == "resume_after_s") resume = probe::number(name, value);
      else if (name == "loss") loss = probe::number(name, value);
      else if (name == "delay_ms") delay_ms = probe::number(name, value);
      else if (name == "jitter_ms") jitter_ms = probe::number(name, value);
      else if (name == "rate_hz") c.rate_hz = probe::number(name, value);
      else if (name == "latency_s") c.latency_s = probe::number(name, value);
      else if (name == "position_sigma_m") c.position_sigma_m = probe::number(name, value);
      else if (name == "angle_sigma_deg") c.angle_sigma_rad = probe::number(name, value) * std::numbers::pi / 180.0;
      else if (name == "seed") c.seed = static_cast<std::uint64_t>(probe::number(name, value));
      else if (name == "with_head") with_head = value == "true";
      else if (name == "head_p_W_m") probe::vector3(name, value, head_p_W_m.emplace().data());
      else if (name == "delivery_log") log = value;
      else throw std::invalid_argument("unknown parameter '" + name + "'");
    }
    if (!(loss >= 0.0 && loss <= 1.0)) throw std::invalid_argument("parameter 'loss' must be in [0, 1]");
    if (!(delay_ms >= 0.0 && jitter_ms >= 0.0)) throw std::invalid_argument("delay_ms and jitter_ms must be >= 0");
    auto t = std::make_unique<Tracker>(c);
    t->host = host;
    t->silent_after_s = silent;
    t->resume_after_s = resume;
    t->loss = loss;
    t->delay_s = delay_ms * 1e-3;
    t->jitter_s = jitter_ms * 1e-3;
    t->with_head = with_head;
    if (head_p_W_m) {
      const double q_W_wxyz[4] = {1.0, 0.0, 0.0, 0.0};
      host->sim_world->set_head(host->sim_world->context, head_p_W_m->data(), q_W_wxyz);
    }
    t->delivered.open(log, 1u << 18);
    return t.release();
  });
}

mhd_status start(mhd_plugin_instance* self, mhd_error* err) {
  Tracker& t = *of(self);
  t.t_start_s = probe::now_s(*t.host);
  try {
    t.model.start(t.t_start_s, truth_of(*t.host->sim_world));
  } catch (const std::exception& e) {
    probe::set_error(err, e.what());
    return MHD_ERROR;
  }
  return MHD_OK;
}

void close_tracker(mhd_plugin_instance* self) {
  of(self)->delivered.write();
  delete of(self);
}

/// Advances the model; what it measured goes in flight with its delivery time, or is lost.
mhd_status simulate_until(mhd_plugin_instance* self, double t_s, mhd_error* err) {
  Tracker& t = *of(self);
  try {
    t.model.simulate_until(t_s, truth_of(*t.host->sim_world));
  } catch (const std::exception& e) {
    probe::set_error(err, e.what());
    return MHD_ERROR;
  }
  std::array<mhd_tracker_sample, 32> measured{};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (;;) {
    const std::size_t n = t.model.read(measured);
    for (std::size_t i = 0; i < n; ++i) {
      const mhd_tracker_sample& s = measured[i];
      if (s.sensor_id != 0 && !t.with_head) continue;
      const double since_start_s = s.timestamp_s - t.t_start_s;
      if (since_start_s >= t.silent_after_s && since_start_s < t.resume_after_s) continue;
      if (t.loss > 0.0 && unit(t.rng) < t.loss) continue;
      double extra_s = t.delay_s;
      if (t.jitter_s > 0.0) extra_s += t.jitter_s * (2.0 * unit(t.rng) - 1.0);
      // The model already held it for its latency; the extra delay comes on top, in order.
      const double arrival_s = std::max(t.last_arrival_s, s.timestamp_s + t.model.config().latency_s + std::max(0.0, extra_s));
      t.last_arrival_s = arrival_s;
      t.in_flight.push_back({s, arrival_s});
    }
    if (n < measured.size()) break;
  }
  return MHD_OK;
}

mhd_status read(mhd_plugin_instance* self, mhd_tracker_sample* out, size_t capacity, size_t* count, mhd_error*) {
  Tracker& t = *of(self);
  const double now = probe::now_s(*t.host);
  std::size_t n = 0;
  while (n < capacity && !t.in_flight.empty() && t.in_flight.front().arrival_s <= now) {
    const Pending& p = t.in_flight.front();
    out[n++] = p.sample;
    t.delivered.add(p.sample.timestamp_s, now, static_cast<double>(p.sample.sequence), p.sample.sensor_id);
    t.in_flight.pop_front();
  }
  *count = n;
  return n == 0 ? MHD_NO_DATA : MHD_OK;
}

}  // namespace

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return nullptr;
  static const mhd_plugin_api api = [] {
    mhd_plugin_api a = probe::table("test tracker: the simulated IS-900 falling silent, lossy or jittery on cue");
    a.open = open_tracker;
    a.start = start;
    a.close = close_tracker;
    // Declared as text: this probe parses its own values, the host checks only the names.
    static const mhd_param_decl params[] = {
        {"silent_after_s", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"resume_after_s", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"loss", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"delay_ms", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"jitter_ms", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"rate_hz", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"latency_s", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"position_sigma_m", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"angle_sigma_deg", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"seed", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"with_head", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"head_p_W_m", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
        {"delivery_log", MHD_PARAM_TEXT, "", 0u, 0.0, 0.0, nullptr, nullptr, "test probe parameter"},
    };
    a.params = params;
    a.param_count = sizeof(params) / sizeof(params[0]);
    a.tracker_read = read;
    a.simulate_until = simulate_until;
    return a;
  }();
  return &api;
}
