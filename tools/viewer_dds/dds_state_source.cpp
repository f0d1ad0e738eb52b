#include "viewer_dds/dds_state_source.h"

#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "plugin_host/abi_conversion.h"

#include <fmt/core.h>

#include <chrono>
#include <cstdio>
#include <utility>

namespace mhd::viewer {

double steady_now_s() noexcept {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct DdsStateSource::Impl {
  explicit Impl(const DdsStateSourceOptions& o)
      : options(o),
        participant(o.domain_id ? static_cast<dds_domainid_t>(*o.domain_id) : DDS_DOMAIN_DEFAULT),
        subscriber(participant, dds::rig_partition(o.rig_id), 16) {}

  DdsStateSourceOptions options;
  dds::Participant participant;
  dds::Subscriber<mhd_dds_RigState> subscriber;
  MessageSink sink;
  DdsStateSourceStatus status;
  std::optional<RigState> state;
  std::optional<double> started_s;  // first poll
  double last_arrival_s = 0.0;      // of a valid state
  bool reported_waiting = false;

  void say(const std::string& line) const {
    if (sink) {
      sink(line);
    } else {
      fmt::print(stderr, "mhd viewer: {}\n", line);
    }
  }
};

DdsStateSource::DdsStateSource(const DdsStateSourceOptions& options, MessageSink sink)
    : impl_(std::make_unique<Impl>(options)) {
  impl_->sink = std::move(sink);
}

DdsStateSource::~DdsStateSource() = default;

std::optional<RigState> DdsStateSource::latest() { return poll(steady_now_s()); }

std::optional<RigState> DdsStateSource::poll(double now_s) {
  Impl& s = *impl_;
  if (!s.started_s) s.started_s = now_s;
  const bool had_state = s.state.has_value();
  bool arrived = false;
  // Samples of one instance come oldest first: the last valid one is the newest.
  for (const mhd_dds_RigState& sample : s.subscriber.reader().take()) {
    if (sample.rig_id != s.options.rig_id) {
      ++s.status.other_rigs;
      continue;
    }
    Result<RigState, std::string> converted = rig_state_from_frame(from_abi(dds::from_dds(sample, now_s)));
    if (!converted.ok()) {
      ++s.status.dropped_invalid;
      s.status.last_error = converted.error();
      continue;
    }
    s.state = *converted;
    ++s.status.received;
    arrived = true;
  }

  const double silent_since_s = had_state ? s.last_arrival_s : *s.started_s;
  if (arrived) {
    if (s.status.stale) {
      s.say(fmt::format("{} from rig {} after {:.1f} s", had_state ? "rig state again" : "first rig state",
                        s.options.rig_id, now_s - silent_since_s));
    }
    s.status.stale = false;
    s.last_arrival_s = now_s;
  } else if (!s.status.stale && now_s - silent_since_s >= s.options.stale_after_s) {
    s.status.stale = true;
    if (had_state) {
      s.say(fmt::format("no rig state from rig {} for {:.1f} s (publisher gone?); keeping the last state",
                        s.options.rig_id, now_s - silent_since_s));
    } else {
      s.say(fmt::format("no rig state from rig {} yet after {:.1f} s; drawing the scene only", s.options.rig_id,
                        now_s - silent_since_s));
    }
  }
  s.status.has_state = s.state.has_value();
  return s.state;
}

const DdsStateSourceStatus& DdsStateSource::status() const noexcept { return impl_->status; }

std::uint32_t DdsStateSource::matched_publishers() const { return impl_->subscriber.reader().matched_writers(); }

}  // namespace mhd::viewer
