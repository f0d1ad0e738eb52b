#pragma once
// MHD's topics: one name, type and QoS per sample type (mhd_dds_types.idl).
// Poses and rig state are best-effort keep-last (a late pose is worthless, a resent one
// arrives late); base commands and rig status are reliable. The simulated world
// (simulation only) is best-effort keep-last like a pose. Tracker samples and base
// commands are owned exclusively: per (rig, sensor) instance a reader takes samples
// from the strongest live writer only (docs/networking.md, "Security"). Every endpoint
// lives in its rig's partition (rig_partition.h).

#include "dds_common/dds_entity.h"
#include "dds_common/rig_partition.h"
#include "mhd_dds_types.h"

#include <cstdint>
#include <string>

namespace mhd::dds {

template <>
struct TopicTraits<mhd_dds_TrackerSample> {
  static constexpr const char* name = "mhd_tracker_sample";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_TrackerSample_desc; }
  /// Per (rig, sensor) instance: 190 Hz read at 1 kHz never needs more than a few.
  /// A killed tracker server's writer keeps the sensors for this long; then a restarted
  /// one (same strength) or a weaker one takes over.
  static constexpr dds_duration_t kLiveliness_ns = DDS_MSECS(500);
  static Qos qos() {
    Qos q = Qos::best_effort(16);
    q.exclusive_ownership().automatic_liveliness(kLiveliness_ns);
    return q;
  }
};

template <>
struct TopicTraits<mhd_dds_RigState> {
  static constexpr const char* name = "mhd_rig_state";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_RigState_desc; }
  static Qos qos() { return Qos::best_effort(4); }
};

template <>
struct TopicTraits<mhd_dds_BaseCommand> {
  static constexpr const char* name = "mhd_base_command";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_BaseCommand_desc; }
  static Qos qos() {
    Qos q = Qos::reliable(8);
    q.exclusive_ownership();
    return q;
  }
};

template <>
struct TopicTraits<mhd_dds_RigStatus> {
  static constexpr const char* name = "mhd_rig_status";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_RigStatus_desc; }
  static Qos qos() { return Qos::reliable(1, /*transient_local=*/true); }
};

template <>
struct TopicTraits<mhd_dds_SimWorld> {
  static constexpr const char* name = "mhd_sim_world";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_SimWorld_desc; }
  static Qos qos() { return Qos::best_effort(4); }
};

template <>
struct TopicTraits<mhd_dds_RigClaim> {
  static constexpr const char* name = "mhd_rig_claim";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_RigClaim_desc; }
  /// A killed claimant's claim is gone after this; then a restarted process may claim.
  static constexpr dds_duration_t kLiveliness_ns = DDS_MSECS(1000);
  static Qos qos() {
    Qos q = Qos::reliable(1, /*transient_local=*/true);
    q.automatic_liveliness(kLiveliness_ns);
    return q;
  }
};

template <>
struct TopicTraits<mhd_dds_SharedObject> {
  static constexpr const char* name = "mhd_shared_object";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_SharedObject_desc; }
  /// Per (rig, object, kind): read every millisecond, a few cover the jitter.
  static Qos qos() { return Qos::best_effort(8); }
};

/// The topic of T in `participant`, with T's name, type and QoS.
template <class T>
[[nodiscard]] Topic make_topic(const Participant& participant) {
  return Topic(participant, TopicTraits<T>::descriptor(), TopicTraits<T>::name, TopicTraits<T>::qos());
}

/// T's QoS for a writer of `ownership_strength` (used where T is owned exclusively).
template <class T>
[[nodiscard]] Qos writer_qos(std::int32_t ownership_strength) {
  Qos q = TopicTraits<T>::qos();
  q.ownership_strength(ownership_strength);
  return q;
}

/// The writer strength of a rig's own publishers: a second writer must be weaker.
inline constexpr std::int32_t kDefaultOwnershipStrength = 10;

/// A topic and a writer of T with T's QoS in `partition` (usually rig_partition(rig)).
/// Throws DdsError NOT_ALLOWED_BY_SECURITY when the identity may not publish T there.
template <class T>
class Publisher {
 public:
  Publisher(const Participant& participant, const std::string& partition,
            std::int32_t ownership_strength = kDefaultOwnershipStrength)
      : topic_(make_topic<T>(participant)),
        group_(participant, PartitionGroup::Side::Publish, partition),
        writer_(group_.handle(), topic_, writer_qos<T>(ownership_strength)) {}
  void write(const T& sample) { writer_.write(sample); }
  [[nodiscard]] const Writer<T>& writer() const { return writer_; }

 private:
  Topic topic_;
  PartitionGroup group_;
  Writer<T> writer_;
};

/// A topic and a reader of T with T's QoS in `partition` (a rig's, or kAllRigsPartition).
template <class T>
class Subscriber {
 public:
  Subscriber(const Participant& participant, const std::string& partition, std::size_t batch = 64)
      : topic_(make_topic<T>(participant)),
        group_(participant, PartitionGroup::Side::Subscribe, partition),
        reader_(group_.handle(), topic_, TopicTraits<T>::qos(), batch) {}
  Subscriber(Subscriber&&) = delete;
  [[nodiscard]] Reader<T>& reader() { return reader_; }
  [[nodiscard]] const Reader<T>& reader() const { return reader_; }

 private:
  Topic topic_;
  PartitionGroup group_;
  Reader<T> reader_;
};

}  // namespace mhd::dds
