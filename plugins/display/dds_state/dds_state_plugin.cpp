// The `dds_state` display plugin: every mhd_display_frame it gets becomes one
// mhd_dds::RigState of its rig, stamped on CLOCK_REALTIME and numbered. Best-effort
// writes never block, so display_write stays cheap on the server's 60 Hz thread.
//
// It is how a haptic process appears on the network as its rig, so it claims the rig id
// (rig_claim.h): it publishes nothing while its claim settles, and a claim refused
// because an older process holds the rig ends the run with the holder named. The holder
// counts every younger claim it refused (counter rig_claims_refused) and says so on
// stderr.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "dds_common/dds_plugin_params.h"
#include "dds_common/rig_claim.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <span>
#include <stdexcept>

namespace mhd::dds_state {

class DdsStatePlugin {
 public:
  static constexpr std::array kParams = sdk::join(
      dds::kEndpointParams,
      std::array{
          sdk::number("claim_settle_s", "s", "1",
                      "how long the rig id's claim waits for older claims before this process publishes as the rig",
                      sdk::between(0, 10)),
      });

  DdsStatePlugin(const mhd_host& host, const sdk::Params& params)
      : DdsStatePlugin(host, dds::read_endpoint(params, host.scene_file), params.number("claim_settle_s")) {}

  void display_write(const mhd_display_frame& frame) {
    switch (claim_.update(dds::realtime_ns())) {
      case dds::RigClaim::Standing::Refused: throw std::runtime_error(claim_.refusal());
      case dds::RigClaim::Standing::Settling: return;  // an older claim may still be on its way
      case dds::RigClaim::Standing::Holding: break;
    }
    report_refusals();
    const std::int64_t stamp_ns = dds::realtime_from_host(frame.timestamp_s, sdk::host_now(host_), dds::realtime_ns());
    publisher_.write(dds::to_dds(frame, rig_id_, sequence_++, stamp_ns));
  }

  std::size_t counters(std::span<mhd_counter> out) {
    if (out.empty()) return 0;
    out[0] = mhd_counter{"rig_claims_refused", claim_.refused()};
    return 1;
  }

 private:
  DdsStatePlugin(const mhd_host& host, const dds::DdsEndpoint& endpoint, double claim_settle_s)
      : host_(host),
        rig_id_(endpoint.rig_id),
        participant_(endpoint.domain_id, endpoint.config, endpoint.identity_dir),
        claim_(participant_, endpoint.rig_id, static_cast<std::int64_t>(claim_settle_s * 1e9)),
        publisher_(participant_, dds::rig_partition(endpoint.rig_id)) {}

  void report_refusals() {
    if (claim_.refused() == reported_) return;
    reported_ = claim_.refused();
    std::fprintf(stderr, "dds_state: rig %u: refused another process's claim of this rig (%llu so far)\n", rig_id_,
                 static_cast<unsigned long long>(reported_));
  }

  mhd_host host_;
  std::uint32_t rig_id_;
  dds::Participant participant_;
  dds::RigClaim claim_;
  dds::Publisher<mhd_dds_RigState> publisher_;
  std::uint64_t sequence_ = 0;
  std::uint64_t reported_ = 0;
};

}  // namespace mhd::dds_state

MHD_PLUGIN_ENTRY(mhd::dds_state::DdsStatePlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.1.0",
                  .description = "Publishes the rig's state (hand, proxy, force, base, head) over Cyclone DDS for "
                                 "viewers, and claims the rig id: a second process with it is refused"})
