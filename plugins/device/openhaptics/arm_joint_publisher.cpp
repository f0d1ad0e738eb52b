#include "arm_joint_publisher.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace mhd_openhaptics {

namespace ros2 = mhd::dds::ros2;

ArmJointPublisher::ArmJointPublisher(const ServoLoop& servo, const mhd::dds::DdsEndpoint& endpoint,
                                     const std::string& ros_topic, double rate_hz)
    : servo_(servo),
      participant_(endpoint.domain_id, endpoint.config, endpoint.identity_dir),
      writer_(participant_, sensor_msgs_msg_dds__JointState__desc, ros2::dds_topic_name("", ros_topic)),
      period_s_(1.0 / rate_hz) {
  for (std::size_t i = 0; i < kJointNames.size(); ++i) names_[i] = const_cast<char*>(kJointNames[i]);
  constexpr auto kJoints = static_cast<std::uint32_t>(kJointNames.size());
  // The C types hold char*; DDS only reads them when writing, and never frees them.
  message_.header.frame_id = const_cast<char*>("");
  message_.name = {._maximum = kJoints, ._length = kJoints, ._buffer = names_.data(), ._release = false};
  message_.position = {._maximum = kJoints, ._length = kJoints, ._buffer = positions_rad_.data(), ._release = false};
  message_.velocity = {._maximum = 0, ._length = 0, ._buffer = nullptr, ._release = false};
  message_.effort = {._maximum = 0, ._length = 0, ._buffer = nullptr, ._release = false};
}

ArmJointPublisher::~ArmJointPublisher() { stop(); }

void ArmJointPublisher::start() {
  running_.store(true, std::memory_order_release);
  thread_ = std::thread([this] { run(); });
}

void ArmJointPublisher::stop() noexcept {
  running_.store(false, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
}

void ArmJointPublisher::run() noexcept {
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(period_s_));
  auto next = std::chrono::steady_clock::now();
  while (running_.load(std::memory_order_acquire)) {
    try {
      publish_newest();
    } catch (const std::exception& e) {
      // A display that cannot be reached is no reason to stop the arm: say it once.
      std::fprintf(stderr, "openhaptics: joint states no longer published: %s\n", e.what());
      return;
    }
    next += period;
    std::this_thread::sleep_until(next);
  }
}

void ArmJointPublisher::publish_newest() {
  const ArmJoints joints = servo_.joints();
  if (joints.frame == last_frame_) return;
  last_frame_ = joints.frame;
  for (const double a : joints.angles_rad) {
    if (!std::isfinite(a)) return;
  }
  positions_rad_ = joints.angles_rad;
  message_.header.stamp = ros2::ros_time(mhd::dds::realtime_ns());
  writer_.write(message_);
  published_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace mhd_openhaptics
