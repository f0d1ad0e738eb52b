// The `dds_link` link plugin: the messages of shared objects (docs/shared-objects.md)
// over Cyclone DDS as mhd_dds::SharedObject. This rig writes in its own partition
// (rig_partition.h), so under DDS Security a rig's identity speaks as that rig only; it
// reads each rig of `other_rigs` in that rig's partition, and refuses (and counts) a
// sample whose rig id is not the partition's. Times travel as CLOCK_REALTIME
// nanoseconds: hosts must be clock-synchronised (NTP/PTP), as for tracking. Best-effort
// writes never block.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_plugin_params.h"
#include "dds_common/dds_topics.h"
#include "dds_common/other_rigs.h"

#include <mhd/plugin_sdk.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd::dds_link {

using Sample = mhd_dds_SharedObject;

class DdsLinkPlugin {
 public:
  static constexpr std::array kParams =
      sdk::join(dds::kEndpointParams, std::array{sdk::text("other_rigs", nullptr,
                                                           "the rigs sharing objects with this one, e.g. \"2 3\"")});

  DdsLinkPlugin(const mhd_host& host, const sdk::Params& params)
      : DdsLinkPlugin(host, dds::read_endpoint(params, host.scene_file),
                      params.optional_text("other_rigs").value_or("")) {}

  void link_send(std::span<const mhd_link_message> messages) {
    const double host_now_s = sdk::host_now(host_);
    const std::int64_t now_ns = dds::realtime_ns();
    for (const mhd_link_message& m : messages) {
      if (m.rig_id != rig_id_) {
        throw std::runtime_error("a message of rig " + std::to_string(m.rig_id) + " given to the link of rig " +
                                 std::to_string(rig_id_) + " (the scene's <sharing rig_id> and the plugin's "
                                 "rig_id must agree)");
      }
      publisher_.write(to_sample(m, dds::realtime_from_host(m.timestamp_s, host_now_s, now_ns)));
      ++sent_;
    }
  }

  std::size_t link_read(std::span<mhd_link_message> out) {
    const double host_now_s = sdk::host_now(host_);
    const std::int64_t now_ns = dds::realtime_ns();
    std::size_t n = 0;
    for (std::size_t r = 0; r < readers_.size() && n < out.size(); ++r) {
      for (const Sample& s : readers_[r]->reader().take()) {
        if (s.rig_id != other_rigs_[r]) {
          ++refused_;  // written in rig other_rigs_[r]'s partition as another rig
          continue;
        }
        if (n == out.size()) {
          ++dropped_;  // the host reads every millisecond; a batch this large is stale anyway
          continue;
        }
        out[n++] = from_sample(s, dds::host_from_realtime(s.timestamp_ns, host_now_s, now_ns));
        ++received_;
      }
    }
    return n;
  }

  std::size_t counters(std::span<mhd_counter> out) const {
    const std::array<mhd_counter, 4> all{{{"link_sent", sent_},
                                          {"link_received", received_},
                                          {"link_refused_wrong_rig", refused_},
                                          {"link_dropped", dropped_}}};
    const std::size_t n = std::min(out.size(), all.size());
    std::copy_n(all.begin(), n, out.begin());
    return all.size();
  }

 private:
  DdsLinkPlugin(const mhd_host& host, const dds::DdsEndpoint& endpoint, const std::string& other_rigs)
      : host_(host),
        rig_id_(endpoint.rig_id),
        other_rigs_(dds::parse_other_rigs(other_rigs, endpoint.rig_id)),
        participant_(endpoint.domain_id, endpoint.config, endpoint.identity_dir),
        publisher_(participant_, dds::rig_partition(endpoint.rig_id)) {
    if (other_rigs_.empty()) throw sdk::ParamError("parameter 'other_rigs' must name the rigs this one shares with");
    for (const std::uint32_t rig : other_rigs_) {
      readers_.push_back(std::make_unique<dds::Subscriber<Sample>>(participant_, dds::rig_partition(rig)));
    }
  }

  // The pose, twist, force and point, which the sample and the message name alike.
  template <class From, class To>
  static void copy_vectors(const From& from, To& to) {
    std::copy_n(from.p_W_m, 3, to.p_W_m);
    std::copy_n(from.q_W_wxyz, 4, to.q_W_wxyz);
    std::copy_n(from.v_W_mps, 3, to.v_W_mps);
    std::copy_n(from.w_W_radps, 3, to.w_W_radps);
    std::copy_n(from.f_W_N, 3, to.f_W_N);
    std::copy_n(from.p_O_m, 3, to.p_O_m);
  }

  static Sample to_sample(const mhd_link_message& m, std::int64_t stamp_ns) {
    Sample s{};
    s.rig_id = m.rig_id;
    s.object_id = m.object_id;
    s.kind = m.kind;
    s.term = m.term;
    s.sequence_number = m.sequence;
    s.timestamp_ns = stamp_ns;
    copy_vectors(m, s);
    return s;
  }

  static mhd_link_message from_sample(const Sample& s, double t_s) {
    mhd_link_message m{};
    m.kind = s.kind;
    m.object_id = s.object_id;
    m.rig_id = s.rig_id;
    m.term = s.term;
    m.sequence = s.sequence_number;
    m.timestamp_s = t_s;
    copy_vectors(s, m);
    return m;
  }

  mhd_host host_;
  std::uint32_t rig_id_;
  std::vector<std::uint32_t> other_rigs_;
  dds::Participant participant_;
  dds::Publisher<Sample> publisher_;
  std::vector<std::unique_ptr<dds::Subscriber<Sample>>> readers_;  // [i]: other_rigs_[i]'s partition
  std::uint64_t sent_ = 0, received_ = 0, refused_ = 0, dropped_ = 0;
};

}  // namespace mhd::dds_link

MHD_PLUGIN_ENTRY(mhd::dds_link::DdsLinkPlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Carries the states and pushes of objects several rigs share over Cyclone DDS"})
