#include "dds_common/peer_watch.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace mhd::dds {
namespace {

std::array<std::uint8_t, 16> key_of(const dds_guid_t& g) {
  std::array<std::uint8_t, 16> k{};
  std::memcpy(k.data(), g.v, k.size());
  return k;
}

/// The participant part of a GUID: its first 12 bytes (the last 4 name the entity).
std::array<std::uint8_t, 16> participant_of(const dds_guid_t& g) {
  std::array<std::uint8_t, 16> k = key_of(g);
  std::fill(k.begin() + 12, k.end(), std::uint8_t{0});
  return k;
}

Entity builtin_reader(const Participant& participant, dds_entity_t topic) {
  return Entity(check(dds_create_reader(participant.handle(), topic, nullptr, nullptr),
                      "dds_create_reader (builtin topic)"));
}

}  // namespace

PeerWatch::PeerWatch(const Participant& participant, std::int64_t grace_ns) : grace_ns_(grace_ns) {
  check(dds_get_guid(participant.handle(), &own_), "dds_get_guid");
  participants_ = builtin_reader(participant, DDS_BUILTIN_TOPIC_DCPSPARTICIPANT);
  publications_ = builtin_reader(participant, DDS_BUILTIN_TOPIC_DCPSPUBLICATION);
  subscriptions_ = builtin_reader(participant, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION);
}

PeerWatch::~PeerWatch() {
  subscriptions_.reset();
  publications_.reset();
  participants_.reset();
}

void PeerWatch::take(dds_entity_t reader, bool endpoints, std::int64_t now_ns) {
  constexpr std::size_t kBatch = 16;
  for (;;) {
    std::array<void*, kBatch> samples{};
    std::array<dds_sample_info_t, kBatch> infos{};
    const dds_return_t n = dds_take(reader, samples.data(), infos.data(), kBatch, kBatch);
    if (n <= 0) return;
    for (dds_return_t i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      if (!infos[k].valid_data) continue;
      if (endpoints) {
        const auto* e = static_cast<const dds_builtintopic_endpoint_t*>(samples[k]);
        peers_[participant_of(e->participant_key)].has_endpoint = true;
      } else {
        const auto* p = static_cast<const dds_builtintopic_participant_t*>(samples[k]);
        Peer& peer = peers_[participant_of(p->key)];
        const std::int64_t heard_ns = std::min(infos[k].source_timestamp, now_ns);
        if (peer.first_heard_ns < 0 || heard_ns < peer.first_heard_ns) peer.first_heard_ns = heard_ns;
      }
    }
    dds_return_loan(reader, samples.data(), n);
  }
}

PeerWatch::Counts PeerWatch::counts(std::int64_t now_ns) {
  const std::array<std::uint8_t, 16> own = participant_of(own_);
  const std::lock_guard lock(mutex_);
  take(participants_.handle(), false, now_ns);
  take(publications_.handle(), true, now_ns);
  take(subscriptions_.handle(), true, now_ns);
  Counts c;
  for (const auto& [key, peer] : peers_) {
    if (key == own || peer.first_heard_ns < 0) continue;
    ++c.heard;
    if (peer.has_endpoint) ++c.admitted;
    else if (now_ns - peer.first_heard_ns > grace_ns_) ++c.refused;
  }
  return c;
}

}  // namespace mhd::dds
