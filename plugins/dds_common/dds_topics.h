#pragma once
// MHD's topics: one name, type and QoS per sample type (mhd_dds_types.idl).
// Poses and rig state are best-effort keep-last (a late pose is worthless, a resent one
// arrives late); base commands and rig status are reliable.

#include "dds_common/dds_entity.h"
#include "mhd_dds_types.h"

namespace mhd::dds {

template <>
struct TopicTraits<mhd_dds_TrackerSample> {
  static constexpr const char* name = "mhd_tracker_sample";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_TrackerSample_desc; }
  /// Per (rig, sensor) instance: 190 Hz read at 1 kHz never needs more than a few.
  static Qos qos() { return Qos::best_effort(16); }
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
  static Qos qos() { return Qos::reliable(8); }
};

template <>
struct TopicTraits<mhd_dds_RigStatus> {
  static constexpr const char* name = "mhd_rig_status";
  static const dds_topic_descriptor_t& descriptor() { return mhd_dds_RigStatus_desc; }
  static Qos qos() { return Qos::reliable(1, /*transient_local=*/true); }
};

/// The topic of T in `participant`, with T's name, type and QoS.
template <class T>
[[nodiscard]] Topic make_topic(const Participant& participant) {
  return Topic(participant, TopicTraits<T>::descriptor(), TopicTraits<T>::name, TopicTraits<T>::qos());
}

/// A topic and a writer of T with T's QoS.
template <class T>
class Publisher {
 public:
  explicit Publisher(const Participant& participant)
      : topic_(make_topic<T>(participant)), writer_(participant, topic_, TopicTraits<T>::qos()) {}
  void write(const T& sample) { writer_.write(sample); }
  [[nodiscard]] const Writer<T>& writer() const { return writer_; }

 private:
  Topic topic_;
  Writer<T> writer_;
};

/// A topic and a reader of T with T's QoS.
template <class T>
class Subscriber {
 public:
  explicit Subscriber(const Participant& participant, std::size_t batch = 64)
      : topic_(make_topic<T>(participant)), reader_(participant, topic_, TopicTraits<T>::qos(), batch) {}
  Subscriber(Subscriber&&) = delete;
  [[nodiscard]] Reader<T>& reader() { return reader_; }

 private:
  Topic topic_;
  Reader<T> reader_;
};

}  // namespace mhd::dds
