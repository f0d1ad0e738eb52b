#include "dds_common/rig_claim.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <ctime>
#include <thread>
#include <tuple>

namespace mhd::dds {

namespace {

std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const char c : s) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

std::string utc_text(std::int64_t ns) {
  const std::time_t t = static_cast<std::time_t>(ns / 1000000000);
  std::tm tm{};
  gmtime_r(&t, &tm);
  std::array<char, 32> text{};
  (void)std::strftime(text.data(), text.size(), "%Y-%m-%d %H:%M:%S UTC", &tm);
  return text.data();
}

// Deeper than the writers' history: a claim and its withdrawal both reach update().
Qos reader_qos() {
  Qos q = Qos::reliable(8, /*transient_local=*/true);
  q.automatic_liveliness(TopicTraits<mhd_dds_RigClaim>::kLiveliness_ns);
  return q;
}

}  // namespace

Claimant this_process() {
  std::array<char, 256> name{};
  if (gethostname(name.data(), name.size() - 1) != 0) name[0] = '\0';
  Claimant c;
  c.host = name.data();
  c.host_id = fnv1a(c.host);
  c.pid = static_cast<std::uint32_t>(getpid());
  return c;
}

RigClaim::RigClaim(const Participant& participant, std::uint32_t rig_id, std::int64_t settle_ns, Claimant self,
                   std::int64_t claimed_ns)
    : rig_id_(rig_id),
      settle_ns_(settle_ns),
      self_(std::move(self)),
      claimed_ns_(claimed_ns),
      topic_(make_topic<mhd_dds_RigClaim>(participant)),
      publisher_(participant, PartitionGroup::Side::Publish, rig_partition(rig_id)),
      subscriber_(participant, PartitionGroup::Side::Subscribe, rig_partition(rig_id)),
      writer_(publisher_.handle(), topic_, TopicTraits<mhd_dds_RigClaim>::qos()),
      reader_(check(dds_create_reader(subscriber_.handle(), topic_.handle(), reader_qos().get(), nullptr),
                    "dds_create_reader")) {
  sample_.rig_id = rig_id_;
  sample_.host_id = self_.host_id;
  sample_.pid = self_.pid;
  sample_.claimed_ns = claimed_ns_;
  std::strncpy(sample_.host, self_.host.c_str(), sizeof(sample_.host) - 1);
  writer_.write(sample_);
}

RigClaim::~RigClaim() {
  if (refused_self_ && !withdrawn_) {
    // A refused process ends at once: its claim stays until the holder has counted it
    // (and said so), but no longer than a claim takes to settle.
    const auto end = std::chrono::steady_clock::now() + std::chrono::nanoseconds(settle_ns_);
    while (!withdrawn_ && std::chrono::steady_clock::now() < end) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      take();
      if (holder_counted_self()) withdraw();
    }
  }
  withdraw();
}

bool RigClaim::holder_counted_self() const {
  return counted_by_.contains(holder_key_);
}

void RigClaim::withdraw() {
  if (withdrawn_) return;
  withdrawn_ = true;
  (void)dds_dispose(writer_.handle(), &sample_);
}

bool RigClaim::older_than_self(const Key& key, const Live& claim) const {
  return std::tie(claim.claimed_ns, key.first, key.second) < std::tie(claimed_ns_, self_.host_id, self_.pid);
}

void RigClaim::take() {
  constexpr std::size_t kBatch = 16;
  std::array<mhd_dds_RigClaim, kBatch> samples{};
  std::array<void*, kBatch> pointers{};
  std::array<dds_sample_info_t, kBatch> infos{};
  for (std::size_t i = 0; i < kBatch; ++i) pointers[i] = &samples[i];
  for (;;) {
    const dds_return_t n = check(dds_take(reader_.handle(), pointers.data(), infos.data(), kBatch, kBatch), "dds_take");
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
      const mhd_dds_RigClaim& s = samples[i];
      const Key key{s.host_id, s.pid};
      if (s.rig_id != rig_id_ || key == Key{self_.host_id, self_.pid}) continue;
      if (infos[i].valid_data) {
        Live claim{s.claimed_ns, std::string(s.host, strnlen(s.host, sizeof(s.host)))};
        if (Key{s.refused_host_id, s.refused_pid} == Key{self_.host_id, self_.pid}) counted_by_.insert(key);
        // A younger claim is counted even when it was withdrawn before this take; the
        // claim written again with its key tells that claimant it may go.
        if (!refused_self_ && !older_than_self(key, claim) && counted_.insert(key).second) {
          ++refused_;
          sample_.refused_host_id = key.first;
          sample_.refused_pid = key.second;
          writer_.write(sample_);
        }
        if (infos[i].instance_state == DDS_IST_ALIVE) live_[key] = std::move(claim);
      }
      if (infos[i].instance_state != DDS_IST_ALIVE) live_.erase(key);
    }
    if (static_cast<std::size_t>(n) < kBatch) return;
  }
}

RigClaim::Standing RigClaim::update(std::int64_t now_ns) {
  if (refused_self_) {
    if (!withdrawn_) {
      take();
      if (holder_counted_self()) withdraw();
    }
    return Standing::Refused;
  }
  take();
  for (const auto& [key, claim] : live_) {
    if (older_than_self(key, claim)) {
      refused_self_ = true;
      holder_ = claim;
      holder_key_ = key;
      holder_name_ = claim.host + ":" + std::to_string(key.second);
      if (holder_counted_self()) withdraw();
      return Standing::Refused;
    }
  }
  return now_ns - claimed_ns_ < settle_ns_ ? Standing::Settling : Standing::Holding;
}

std::string RigClaim::refusal() const {
  if (!holder_) return {};
  return "rig " + std::to_string(rig_id_) + " is already claimed by " + holder_name_ + " (since " +
         utc_text(holder_->claimed_ns) + "); this process (" + self_.name() + ") may not run as rig " +
         std::to_string(rig_id_);
}

}  // namespace mhd::dds
