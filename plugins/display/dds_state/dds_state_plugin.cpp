// The `dds_state` display plugin: every mhd_display_frame it gets becomes one
// mhd_dds::RigState of its rig, stamped on CLOCK_REALTIME and numbered. Best-effort
// writes never block, so display_write stays cheap on the server's 60 Hz thread.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "dds_common/dds_plugin_params.h"
#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include <mhd/plugin_abi.h>

#include <atomic>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace mhd::dds_state {
namespace {

using plugin_support::guarded_open;

struct Instance {
  Instance(const mhd_host& h, const dds::DdsEndpoint& c)
      : host(h),
        config(c),
        participant(c.domain_id, c.config, c.identity_dir),
        publisher(participant, dds::rig_partition(c.rig_id)) {}

  std::atomic<bool> in_call{false};  ///< plugin_support::with_instance's
  mhd_host host;
  dds::DdsEndpoint config;
  dds::Participant participant;
  dds::Publisher<mhd_dds_RigState> publisher;
  std::uint64_t sequence = 0;
  bool started = false;
};

constexpr auto kParams = dds::kEndpointParams;

dds::DdsEndpoint read_config(const mhd_param* params, std::size_t count, const char* scene_file) {
  plugin_support::ParamReader reader(kParams, params, count);
  const dds::DdsEndpoint endpoint = dds::read_endpoint(reader, params, count, scene_file);
  reader.reject_unknown();
  return endpoint;
}

mhd_plugin_instance* open_instance(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err) {
  return guarded_open(err, [&] {
    plugin_support::check_host(host);
    const dds::DdsEndpoint config = read_config(params, param_count, host->scene_file);
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
    s.started = false;
    return MHD_OK;
  });
}

void close_instance(mhd_plugin_instance* self) { delete reinterpret_cast<Instance*>(self); }

mhd_status display_write(mhd_plugin_instance* self, const mhd_display_frame* frame, mhd_error* err) {
  return call(self, plugin_support::Need::Running, err, [&](Instance& s) {
    if (frame == nullptr) throw std::invalid_argument("display_write: NULL frame");
    const std::int64_t stamp_ns =
        dds::realtime_from_host(frame->timestamp_s, plugin_support::host_now(s.host), dds::realtime_ns());
    s.publisher.write(dds::to_dds(*frame, s.config.rig_id, s.sequence++, stamp_ns));
    return MHD_OK;
  });
}

constexpr mhd_plugin_api kApi = {
    .abi_version = MHD_PLUGIN_ABI_VERSION,
    .struct_size = sizeof(mhd_plugin_api),
    .kind = MHD_PLUGIN_KIND,
    .name = MHD_PLUGIN_NAME,
    .version = "1.0.0",
    .description = "Publishes the rig's state (hand, proxy, force, base, head) over Cyclone DDS for viewers",
    .open = open_instance,
    .start = start_instance,
    .stop = stop_instance,
    .close = close_instance,
    .params = kParams.data(),
    .param_count = kParams.size(),
    .device_info = nullptr,
    .device_read = nullptr,
    .device_write = nullptr,
    .tracker_read = nullptr,
    .base_read = nullptr,
    .base_write = nullptr,
    .display_write = display_write,
    .simulate_until = nullptr,
    .tracker_wait = nullptr,
    .counters = nullptr,
};

}  // namespace
}  // namespace mhd::dds_state

extern "C" MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  return host_abi_version == MHD_PLUGIN_ABI_VERSION ? &mhd::dds_state::kApi : nullptr;
}
