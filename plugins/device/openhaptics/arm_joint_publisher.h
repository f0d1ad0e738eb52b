#pragma once
// The arm's joint angles to ROS 2 displays (rviz2's RobotModel, `ros2 topic echo`): a
// thread of its own, never the haptic or the servo one, that publishes the servo loop's
// newest joints as sensor_msgs/msg/JointState over Cyclone DDS at a fixed rate. Joint
// names are those of the Touch's ROS description: waist, shoulder, elbow (HDAPI's joint
// angles), then wrist1 to wrist3 (its gimbal angles). A reading with a non-finite angle
// is not published; nor is one the servo loop has not renewed since the last.

#include "servo_loop.h"

#include "dds_common/dds_plugin_params.h"
#include "dds_common/ros2_messages.h"
#include "dds_common/ros2_topics.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

namespace mhd_openhaptics {

class ArmJointPublisher {
 public:
  static constexpr std::array<const char*, 6> kJointNames{"waist", "shoulder", "elbow", "wrist1", "wrist2", "wrist3"};

  /// Opens the participant and the topic `ros_topic` (a ROS name: "/touch/joint_states");
  /// publishing starts with start().
  ArmJointPublisher(const ServoLoop& servo, const mhd::dds::DdsEndpoint& endpoint, const std::string& ros_topic,
                    double rate_hz);
  ~ArmJointPublisher();  ///< stop()
  ArmJointPublisher(const ArmJointPublisher&) = delete;
  ArmJointPublisher& operator=(const ArmJointPublisher&) = delete;

  void start();
  void stop() noexcept;
  [[nodiscard]] std::uint64_t published() const noexcept { return published_.load(std::memory_order_relaxed); }

 private:
  void run() noexcept;
  void publish_newest();

  const ServoLoop& servo_;
  mhd::dds::Participant participant_;
  mhd::dds::ros2::RosPublisher<mhd::dds::ros2::JointState> writer_;
  double period_s_;
  mhd::dds::ros2::JointState message_{};
  std::array<char*, 6> names_{};
  std::array<double, 6> positions_rad_{};
  std::uint64_t last_frame_ = 0;
  std::atomic<bool> running_{false};
  std::atomic<std::uint64_t> published_{0};
  std::thread thread_;
};

}  // namespace mhd_openhaptics
