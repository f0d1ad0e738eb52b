// A tracker for the fault-injection suite: the simulated IS-900 (sim_is900's Is900Model,
// measuring the scene's simulated base and head, sim_world/sim_session.h) with delivery faults on top. The
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
#include "sim_world/sim_session.h"
#include "world_truth.h"

#include <algorithm>
#include <array>
#include <deque>
#include <limits>
#include <numbers>
#include <random>
#include <span>
#include <stdexcept>

namespace {

struct Pending {
  mhd_tracker_sample sample;
  double arrival_s;
};

class FiTracker {
 public:
  static constexpr std::array kParams{
      mhd::sdk::number("silent_after_s", "s", nullptr, "nothing measured from then (after start; absent: never)"),
      mhd::sdk::number("resume_after_s", "s", nullptr, "measured again from then (after start; absent: never)"),
      mhd::sdk::number("loss", "", "0", "each sample is lost with this probability", mhd::sdk::between(0.0, 1.0)),
      mhd::sdk::number("delay_ms", "ms", "0", "extra delivery delay", mhd::sdk::non_negative()),
      mhd::sdk::number("jitter_ms", "ms", "0", "extra delay +- U(jitter_ms)", mhd::sdk::non_negative()),
      mhd::sdk::number("rate_hz", "Hz", nullptr, "the IS-900 model's rate (default the model's)", mhd::sdk::positive()),
      mhd::sdk::number("latency_s", "s", nullptr, "the model's latency (default the model's)",
                       mhd::sdk::non_negative()),
      mhd::sdk::number("position_sigma_m", "m", nullptr, "the model's position noise", mhd::sdk::non_negative()),
      mhd::sdk::number("angle_sigma_deg", "deg", nullptr, "the model's angle noise", mhd::sdk::non_negative()),
      mhd::sdk::integer("seed", "", "1", "the model's and the faults' random numbers"),
      mhd::sdk::boolean("with_head", "true", "also deliver the head sensor (id 1)"),
      mhd::sdk::vector3("head_p_W_m", "m", nullptr, "at start, stand the simulated user's head here"),
      mhd::sdk::text("delivery_log", nullptr, "where close() writes every delivered sample"),
  };

  FiTracker(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host),
        session_(mhd::sim_world::SimSession::acquire(host)),
        model_(config_from(params)),
        rng_(model_.config().seed ^ 0x5eedu),
        silent_after_s_(params.optional_number("silent_after_s").value_or(std::numeric_limits<double>::infinity())),
        resume_after_s_(params.optional_number("resume_after_s").value_or(std::numeric_limits<double>::infinity())),
        loss_(params.number("loss")),
        delay_s_(params.number("delay_ms") * 1e-3),
        jitter_s_(params.number("jitter_ms") * 1e-3),
        with_head_(params.boolean("with_head")) {
    if (const auto head_p_W_m = params.optional_vector3("head_p_W_m")) {
      const auto& p = *head_p_W_m;
      session_->world().set_head({Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Quaterniond::Identity()});
    }
    delivered_.open(params.optional_text("delivery_log").value_or(""), 1u << 18);
  }
  FiTracker(const FiTracker&) = delete;
  FiTracker& operator=(const FiTracker&) = delete;
  ~FiTracker() { delivered_.write(); }

  void start() {
    t_start_s_ = mhd::sdk::host_now(host_);
    session_->advance_to(t_start_s_);
    model_.start(t_start_s_, mhd::sim_is900::world_truth(session_->world()));
  }

  /// Advances the model; what it measured goes in flight with its delivery time, or is lost.
  void simulate_until(double t_s) {
    session_->advance_to(t_s);
    model_.simulate_until(t_s, mhd::sim_is900::world_truth(session_->world()));
    std::array<mhd_tracker_sample, 32> measured{};
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (;;) {
      const std::size_t n = model_.read(measured);
      for (std::size_t i = 0; i < n; ++i) {
        const mhd_tracker_sample& s = measured[i];
        if (s.sensor_id != 0 && !with_head_) continue;
        const double since_start_s = s.timestamp_s - t_start_s_;
        if (since_start_s >= silent_after_s_ && since_start_s < resume_after_s_) continue;
        if (loss_ > 0.0 && unit(rng_) < loss_) continue;
        double extra_s = delay_s_;
        if (jitter_s_ > 0.0) extra_s += jitter_s_ * (2.0 * unit(rng_) - 1.0);
        // The model already held it for its latency; the extra delay comes on top, in order.
        const double arrival_s =
            std::max(last_arrival_s_, s.timestamp_s + model_.config().latency_s + std::max(0.0, extra_s));
        last_arrival_s_ = arrival_s;
        in_flight_.push_back({s, arrival_s});
      }
      if (n < measured.size()) break;
    }
  }

  std::size_t tracker_read(std::span<mhd_tracker_sample> out) {
    const double now = mhd::sdk::host_now(host_);
    std::size_t n = 0;
    while (n < out.size() && !in_flight_.empty() && in_flight_.front().arrival_s <= now) {
      const Pending& p = in_flight_.front();
      out[n++] = p.sample;
      delivered_.add(p.sample.timestamp_s, now, static_cast<double>(p.sample.sequence), p.sample.sensor_id);
      in_flight_.pop_front();
    }
    return n;
  }

 private:
  static mhd::sim_is900::Is900Config config_from(const mhd::sdk::Params& params) {
    mhd::sim_is900::Is900Config c;
    c.seed = params.integer("seed");
    c.rate_hz = params.optional_number("rate_hz").value_or(c.rate_hz);
    c.latency_s = params.optional_number("latency_s").value_or(c.latency_s);
    c.position_sigma_m = params.optional_number("position_sigma_m").value_or(c.position_sigma_m);
    if (const auto deg = params.optional_number("angle_sigma_deg")) c.angle_sigma_rad = *deg * std::numbers::pi / 180.0;
    return c;
  }

  mhd_host host_;
  std::shared_ptr<mhd::sim_world::SimSession> session_;
  mhd::sim_is900::Is900Model model_;
  std::mt19937_64 rng_;
  double silent_after_s_, resume_after_s_;
  double loss_, delay_s_, jitter_s_;
  bool with_head_;
  double t_start_s_ = 0.0;
  double last_arrival_s_ = -std::numeric_limits<double>::infinity();
  std::deque<Pending> in_flight_;
  probe::Log delivered_;
};

}  // namespace

MHD_PLUGIN_ENTRY(FiTracker,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "test tracker: the simulated IS-900 falling silent, lossy or jittery on cue"})
