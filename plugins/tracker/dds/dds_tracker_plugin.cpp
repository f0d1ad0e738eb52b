// The `dds` tracker plugin: subscribes to one rig's tracker samples on a DDS domain and
// returns the valid ones from tracker_read (dds_common/tracker_subscriber.h). tracker_wait
// blocks on a DDS waitset, so the host takes a sample as soon as it arrives. Invalid
// samples are dropped and counted; the host reads the counts through counters (its
// status line shows them) and they are printed to stderr when the plugin stops.
// With `other_rigs` it also reads those rigs' samples, each validated as its own rig's,
// and hands out sensor S of rig R as sensor 1000 R + S (dds_common/other_rigs.h).

#include "dds_common/dds_convert.h"
#include "dds_common/shared_sim_world.h"
#include "dds_common/tracker_subscriber.h"
#include "dds_common/dds_plugin_params.h"
#include "dds_common/other_rigs.h"
#include "sim_world/sim_session.h"

#include <mhd/plugin_sdk.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

namespace mhd::dds_tracker {

struct Config {
  dds::DdsEndpoint endpoint;
  dds::TrackerValidationLimits limits;
  bool publish_sim_world = false;
  std::vector<std::uint32_t> other_rigs;
};

// Counter names in DropReason order, after "accepted", then the writers matched now and
// ever (under DDS Security a refused writer never matches), then the remote participants
// heard and refused (peer_watch.h) and Cyclone's logged refusals (security_refusal_log.h);
// static strings, as the ABI asks.
constexpr std::size_t kPeerCounters = 3;
constexpr std::array<const char*, 1 + dds::kDropReasonCount + 2 + kPeerCounters> kCounterNames = {
    "accepted",        "dropped_unknown_rig", "dropped_non_finite",       "dropped_out_of_range",
    "dropped_bad_quaternion", "dropped_stale", "dropped_future", "dropped_sequence_backwards",
    "writers_matched", "writers_matched_total", "peers_heard", "peers_refused", "security_refusals"};

class DdsTrackerPlugin {
 public:
  static constexpr std::array kParams = sdk::join(
      dds::kEndpointParams,
      std::array{
          sdk::number("max_position_m", "m", "20", "samples farther out, per coordinate, are refused",
                      sdk::above_up_to(0, 1000)),
          sdk::number("max_age_s", "s", "0.1", "older samples are stale and refused", sdk::above_up_to(0, 10)),
          sdk::number("max_future_s", "s", "0.01", "clock skew allowed for samples from the future",
                      sdk::between(0, 10)),
          sdk::number("restart_after_s", "s", "0.25", "a silent writer may restart its sequence after this",
                      sdk::above_up_to(0, 60)),
          sdk::number("quaternion_tolerance", "", "0.001", "| |q| - 1 | allowed", sdk::above_up_to(0, 1)),
          sdk::boolean("publish_sim_world", "false", "publish the scene's simulated world (mhd_sim_world topic)"),
          sdk::text("other_rigs", nullptr,
                    "rig ids whose samples this rig also reads; sensor S of rig R arrives as sensor 1000 R + S"),
      });

  DdsTrackerPlugin(const mhd_host& host, const sdk::Params& params)
      : DdsTrackerPlugin(host, read_config(host, params)) {}

  void stop() {
    const dds::PeerWatch::Counts peers = subscriber_.peers(dds_time());
    std::fprintf(stderr,
                 "dds tracker (rig %u): %s; writers matched: %u now, %u ever; peers: %u heard, %u refused; "
                 "security refusals logged: %llu\n",
                 static_cast<unsigned>(config_.limits.rig_id), subscriber_.counts().summary().c_str(),
                 static_cast<unsigned>(subscriber_.writer_matches().current_count),
                 static_cast<unsigned>(subscriber_.writer_matches().total_count), peers.heard, peers.refused,
                 static_cast<unsigned long long>(dds::TrackerSubscriber::security_refusals()));
  }

  std::size_t tracker_read(std::span<mhd_tracker_sample> out) {
    const double host_now_s = sdk::host_now(host_);
    const std::int64_t now_ns = dds::realtime_ns();
    std::size_t n = subscriber_.poll(out, host_now_s, now_ns);
    for (std::size_t i = 0; i < others_.size() && n < out.size(); ++i) {
      const std::size_t m = others_[i]->poll(out.subspan(n), host_now_s, now_ns);
      for (std::size_t k = n; k < n + m; ++k) out[k].sensor_id = dds::other_rig_sensor_id(config_.other_rigs[i], out[k].sensor_id);
      n += m;
    }
    return n;
  }

  mhd_status tracker_wait(double timeout_s) {
    const auto timeout_ns = static_cast<dds_duration_t>(std::clamp(timeout_s, 0.0, 1.0) * 1e9);
    return subscriber_.wait(timeout_ns) ? MHD_OK : MHD_NO_DATA;
  }

  // The host calls this after the simulated base has moved to t_s: the world the remote
  // simulated tracker measures is this process's, with its user at this moment.
  void simulate_until(double t_s) {
    if (sim_world_) {
      session_->advance_to(t_s);
      sim_world_->publish(session_->world(), dds::realtime_from_host(t_s, sdk::host_now(host_), dds::realtime_ns()));
    }
  }

  std::size_t counters(std::span<mhd_counter> out) {
    const dds::DropCounts& c = subscriber_.counts();
    const dds_subscription_matched_status_t matched = subscriber_.writer_matches();
    const dds::PeerWatch::Counts peers = subscriber_.peers(dds_time());
    for (std::size_t i = 0; i < kCounterNames.size() && i < out.size(); ++i) {
      std::uint64_t value = 0;
      if (i == 0) value = c.accepted;
      else if (i <= dds::kDropReasonCount) value = c.dropped[i - 1];
      else if (i == dds::kDropReasonCount + 1) value = matched.current_count;
      else if (i == dds::kDropReasonCount + 2) value = matched.total_count;
      else if (i == dds::kDropReasonCount + 3) value = peers.heard;
      else if (i == dds::kDropReasonCount + 4) value = peers.refused;
      else value = dds::TrackerSubscriber::security_refusals();
      out[i] = {kCounterNames[i], value};
    }
    return kCounterNames.size();
  }

 private:
  DdsTrackerPlugin(const mhd_host& host, const Config& c)
      : host_(host), config_(c), participant_(c.endpoint.domain_id, c.endpoint.config, c.endpoint.identity_dir),
        subscriber_(participant_, c.limits) {
    for (const std::uint32_t rig : c.other_rigs) {
      dds::TrackerValidationLimits limits = c.limits;
      limits.rig_id = rig;
      others_.push_back(std::make_unique<dds::TrackerSubscriber>(participant_, limits));
    }
    if (c.publish_sim_world) {
      session_ = sim_world::SimSession::acquire(host);
      sim_world_.emplace(participant_, c.endpoint.rig_id);
    }
  }

  static Config read_config(const mhd_host& host, const sdk::Params& params) {
    Config c;
    c.endpoint = dds::read_endpoint(params, host.scene_file);
    c.limits.rig_id = c.endpoint.rig_id;
    c.limits.max_abs_position_m = params.number("max_position_m");
    c.limits.max_age_s = params.number("max_age_s");
    c.limits.max_future_s = params.number("max_future_s");
    c.limits.restart_after_s = params.number("restart_after_s");
    c.limits.quaternion_tolerance = params.number("quaternion_tolerance");
    c.publish_sim_world = params.boolean("publish_sim_world");
    c.other_rigs = dds::parse_other_rigs(params.optional_text("other_rigs").value_or(""), c.endpoint.rig_id);
    return c;
  }

  mhd_host host_;
  Config config_;
  dds::Participant participant_;
  dds::TrackerSubscriber subscriber_;
  std::vector<std::unique_ptr<dds::TrackerSubscriber>> others_;  ///< one per config_.other_rigs
  std::shared_ptr<sim_world::SimSession> session_;  ///< with publish_sim_world: this scene's simulated world
  std::optional<dds::SimWorldPublisher> sim_world_;
};

}  // namespace mhd::dds_tracker

MHD_PLUGIN_ENTRY(mhd::dds_tracker::DdsTrackerPlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Tracker samples of one rig over Cyclone DDS (from mhd tracker-server), validated"})
