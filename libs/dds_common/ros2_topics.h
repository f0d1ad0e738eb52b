#pragma once
// ROS 2's side of DDS, as rmw_cyclonedds sets it up: a ROS topic "/ns/name" is the DDS
// topic "rt/ns/name" in the default partition (ROS 2 uses no partitions), and ROS's
// default QoS is reliable, volatile, keep-last 10. A reliable writer also serves
// best-effort readers (rviz2's "sensor data" profile); a best-effort one would match no
// reliable reader, which is what `ros2 topic echo` and rviz2 create by default.

#include "dds_common/dds_entity.h"
#include "dds_common/ros2_messages.h"

#include <string>

namespace mhd::dds::ros2 {

/// ROS 2's default QoS profile (rmw_qos_profile_default).
[[nodiscard]] inline Qos default_qos() { return Qos::reliable(10); }

/// The topic names MHD publishes under a rig's namespace (docs/networking.md, "ROS 2").
struct TopicNames {
  static constexpr const char* hip = "hip_pose";
  static constexpr const char* proxy = "proxy_pose";
  static constexpr const char* base = "base_pose";
  static constexpr const char* head = "head_pose";
  static constexpr const char* force = "force";
  static constexpr const char* joints = "joint_states";
};

/// A topic and a writer of T in the participant's default partition, ROS 2's QoS.
/// Throws DdsError NOT_ALLOWED_BY_SECURITY when the identity may not publish the topic.
template <class T>
class RosPublisher {
 public:
  RosPublisher(const Participant& participant, const dds_topic_descriptor_t& descriptor, const std::string& dds_name)
      : topic_(participant, descriptor, dds_name.c_str(), default_qos()),
        writer_(participant.handle(), topic_, default_qos()) {}
  /// Keep-last 10 holds at most 10 unacknowledged samples, far below the amount at which
  /// Cyclone makes a reliable writer wait, so a slow reader does not block this.
  void write(const T& sample) { writer_.write(sample); }
  [[nodiscard]] const Writer<T>& writer() const { return writer_; }

 private:
  Topic topic_;
  Writer<T> writer_;
};

}  // namespace mhd::dds::ros2
