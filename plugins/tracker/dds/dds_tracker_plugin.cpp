// The `dds` tracker plugin: subscribes to one rig's tracker samples on a DDS domain and
// returns the valid ones from tracker_read (dds_common/tracker_subscriber.h). tracker_wait
// blocks on a DDS waitset, so the host takes a sample as soon as it arrives. Invalid
// samples are dropped and counted; the host reads the counts through counters (its
// status line shows them) and they are printed to stderr when the plugin stops.

#include "dds_common/dds_convert.h"
#include "dds_common/shared_sim_world.h"
#include "dds_common/tracker_subscriber.h"
#include "dds_common/dds_plugin_params.h"
#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include <mhd/plugin_abi.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <atomic>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace mhd::dds_tracker {
namespace {

using plugin_support::guarded_open;

struct Config {
  dds::DdsEndpoint endpoint;
  dds::TrackerValidationLimits limits;
  bool publish_sim_world = false;
};

struct Instance {
  Instance(const mhd_host& h, const Config& c)
      : host(h), config(c), participant(c.endpoint.domain_id, c.endpoint.config, c.endpoint.identity_dir),
        subscriber(participant, c.limits) {
    if (c.publish_sim_world) sim_world.emplace(participant, c.endpoint.rig_id);
  }

  std::atomic<bool> in_call{false};  ///< plugin_support::with_instance's
  mhd_host host;
  Config config;
  dds::Participant participant;
  dds::TrackerSubscriber subscriber;
  std::optional<dds::SimWorldPublisher> sim_world;
  bool started = false;
};

constexpr std::array kParams = sdk::join(
    dds::kEndpointParams,
    std::array{
        sdk::number("max_position_m", "m", "20", "samples farther out, per coordinate, are refused", sdk::positive()),
        sdk::number("max_age_s", "s", "0.1", "older samples are stale and refused", sdk::positive()),
        sdk::number("max_future_s", "s", "0.01", "clock skew allowed for samples from the future",
                    sdk::non_negative()),
        sdk::number("restart_after_s", "s", "0.25", "a silent writer may restart its sequence after this",
                    sdk::positive()),
        sdk::number("quaternion_tolerance", "", "0.001", "| |q| - 1 | allowed", sdk::positive()),
        sdk::boolean("publish_sim_world", "false", "publish this host's simulated world (mhd_sim_world topic)"),
    });

Config read_config(const mhd_param* params, std::size_t count, const char* scene_file) {
  plugin_support::ParamReader reader(kParams, params, count);
  Config c;
  c.endpoint = dds::read_endpoint(reader, params, count, scene_file);
  c.limits.rig_id = c.endpoint.rig_id;
  c.limits.max_abs_position_m = reader.positive("max_position_m", c.limits.max_abs_position_m);
  c.limits.max_age_s = reader.positive("max_age_s", c.limits.max_age_s);
  c.limits.max_future_s = reader.non_negative("max_future_s", c.limits.max_future_s);
  c.limits.restart_after_s = reader.positive("restart_after_s", c.limits.restart_after_s);
  c.limits.quaternion_tolerance = reader.positive("quaternion_tolerance", c.limits.quaternion_tolerance);
  if (const auto publish = reader.optional_text("publish_sim_world")) {
    if (*publish != "true" && *publish != "false") {
      throw plugin_support::ParamError("parameter 'publish_sim_world' must be 'true' or 'false', got '" + *publish + "'");
    }
    c.publish_sim_world = *publish == "true";
  }
  reader.reject_unknown();
  return c;
}

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err) {
  return guarded_open(err, [&] {
    plugin_support::check_host(host);
    const Config config = read_config(params, param_count, host->scene_file);
    if (config.publish_sim_world && host->sim_world == nullptr) {
      throw std::runtime_error("publish_sim_world: the host has no simulated world (sim_world is NULL)");
    }
    return reinterpret_cast<mhd_plugin_instance*>(new Instance(*host, config));
  });
}

template <class F>
mhd_status call(mhd_plugin_instance* self, plugin_support::Need need, mhd_error* err, F&& f) {
  return plugin_support::with_instance<Instance>(MHD_PLUGIN_NAME, self, need, err, std::forward<F>(f));
}

mhd_status start_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    s.started = true;
    return MHD_OK;
  });
}

mhd_status stop_instance(mhd_plugin_instance* self, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    if (s.started) {
      const dds::PeerWatch::Counts peers = s.subscriber.peers(dds_time());
      std::fprintf(stderr,
                   "dds tracker (rig %u): %s; writers matched: %u now, %u ever; peers: %u heard, %u refused; "
                   "security refusals logged: %llu\n",
                   static_cast<unsigned>(s.config.limits.rig_id), s.subscriber.counts().summary().c_str(),
                   static_cast<unsigned>(s.subscriber.writer_matches().current_count),
                   static_cast<unsigned>(s.subscriber.writer_matches().total_count), peers.heard, peers.refused,
                   static_cast<unsigned long long>(dds::TrackerSubscriber::security_refusals()));
    }
    s.started = false;
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) { delete reinterpret_cast<Instance*>(self); }

mhd_status tracker_read(mhd_plugin_instance* self, mhd_tracker_sample* out, size_t capacity, size_t* count,
                        mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (count == nullptr || (out == nullptr && capacity > 0)) throw std::invalid_argument("tracker_read: NULL output");
    *count = s.subscriber.poll(std::span(out, capacity), plugin_support::host_now(s.host), dds::realtime_ns());
    return *count > 0 ? MHD_OK : MHD_NO_DATA;
  });
}

// The host calls this after its simulated user and base have moved to t_s: the world
// the remote simulated tracker measures is this one, at this moment.
mhd_status simulate_until(mhd_plugin_instance* self, double t_s, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (s.sim_world) {
      s.sim_world->publish(*s.host.sim_world,
                           dds::realtime_from_host(t_s, plugin_support::host_now(s.host), dds::realtime_ns()));
    }
    return MHD_OK;
  });
}

mhd_status tracker_wait(mhd_plugin_instance* self, double timeout_s, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    const auto timeout_ns = static_cast<dds_duration_t>(std::clamp(timeout_s, 0.0, 1.0) * 1e9);
    return s.subscriber.wait(timeout_ns) ? MHD_OK : MHD_NO_DATA;
  });
}

// Counter names in DropReason order, after "accepted", then the writers matched now and
// ever (under DDS Security a refused writer never matches), then the remote participants
// heard and refused (peer_watch.h) and Cyclone's logged refusals (security_refusal_log.h);
// static strings, as the ABI asks.
constexpr std::size_t kPeerCounters = 3;
constexpr std::array<const char*, 1 + dds::kDropReasonCount + 2 + kPeerCounters> kCounterNames = {
    "accepted",        "dropped_unknown_rig", "dropped_non_finite",       "dropped_out_of_range",
    "dropped_bad_quaternion", "dropped_stale", "dropped_future", "dropped_sequence_backwards",
    "writers_matched", "writers_matched_total", "peers_heard", "peers_refused", "security_refusals"};

mhd_status counters(mhd_plugin_instance* self, mhd_counter* out, size_t capacity, size_t* count, mhd_error* err) {
  return call(self, plugin_support::Need::Open, err, [&](Instance& s) {
    if (count == nullptr || (out == nullptr && capacity > 0)) throw std::invalid_argument("counters: NULL output");
    const dds::DropCounts& c = s.subscriber.counts();
    const dds_subscription_matched_status_t matched = s.subscriber.writer_matches();
    const dds::PeerWatch::Counts peers = s.subscriber.peers(dds_time());
    for (std::size_t i = 0; i < kCounterNames.size() && i < capacity; ++i) {
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
    *count = kCounterNames.size();
    return MHD_OK;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,
    .version = "1.0.0",
    .description = "Tracker samples of one rig over Cyclone DDS (from mhd tracker-server), validated",
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
    .tracker_wait = tracker_wait,
    .counters = counters,
};

}  // namespace
}  // namespace mhd::dds_tracker

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::dds_tracker::kApi : nullptr;
}
