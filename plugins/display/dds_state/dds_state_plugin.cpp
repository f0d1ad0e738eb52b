// The `dds_state` display plugin: every mhd_display_frame it gets becomes one
// mhd_dds::RigState of its rig, stamped on CLOCK_REALTIME and numbered. Best-effort
// writes never block, so display_write stays cheap on the server's 60 Hz thread.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "dds_common/dds_plugin_params.h"

#include <mhd/plugin_sdk.hpp>

#include <cstdint>

namespace mhd::dds_state {

class DdsStatePlugin {
 public:
  static constexpr auto kParams = dds::kEndpointParams;

  DdsStatePlugin(const mhd_host& host, const sdk::Params& params)
      : DdsStatePlugin(host, dds::read_endpoint(params, host.scene_file)) {}

  void display_write(const mhd_display_frame& frame) {
    const std::int64_t stamp_ns = dds::realtime_from_host(frame.timestamp_s, sdk::host_now(host_), dds::realtime_ns());
    publisher_.write(dds::to_dds(frame, rig_id_, sequence_++, stamp_ns));
  }

 private:
  DdsStatePlugin(const mhd_host& host, const dds::DdsEndpoint& endpoint)
      : host_(host),
        rig_id_(endpoint.rig_id),
        participant_(endpoint.domain_id, endpoint.config, endpoint.identity_dir),
        publisher_(participant_, dds::rig_partition(endpoint.rig_id)) {}

  mhd_host host_;
  std::uint32_t rig_id_;
  dds::Participant participant_;
  dds::Publisher<mhd_dds_RigState> publisher_;
  std::uint64_t sequence_ = 0;
};

}  // namespace mhd::dds_state

MHD_PLUGIN_ENTRY(mhd::dds_state::DdsStatePlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Publishes the rig's state (hand, proxy, force, base, head) over Cyclone DDS for "
                                 "viewers"})
