// The `ros2_pose` tracker: poses from a motion-capture system's ROS 2 driver (one
// geometry_msgs/PoseStamped topic per role: the base and the head), over Cyclone DDS with
// ROS 2's type names and no ROS dependency. Each pose becomes a tracker sample of its
// role's sensor, in the tracker frame T: the mocap frame the messages name (frame_id), as
// published (ROS's z up); the scene's rig places T in the world (its tracker frame).
// Samples are checked as the `dds` tracker checks its own (sample_validation.h: finite,
// in range, unit quaternion, not stale, not from the future) and, first, for their frame;
// what fails is dropped and counted.

#include "dds_common/dds_convert.h"
#include "dds_common/dds_plugin_params.h"
#include "dds_common/ros2_messages.h"
#include "dds_common/ros2_topics.h"
#include "dds_common/sample_validation.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace mhd::ros2_pose {
namespace ros2 = dds::ros2;

constexpr std::array<const char*, 2 + dds::kDropReasonCount> kCounterNames = {
    "accepted",       "dropped_wrong_frame", "dropped_unknown_rig", "dropped_non_finite",
    "dropped_out_of_range", "dropped_bad_quaternion", "dropped_stale", "dropped_future",
    "dropped_sequence_backwards"};

/// One role's topic and reader (best effort: it matches reliable and "sensor data"
/// publishers alike).
struct RoleReader {
  RoleReader(const dds::Participant& participant, const std::string& topic, std::uint32_t sensor)
      : topic_(participant, geometry_msgs_msg_dds__PoseStamped__desc, ros2::dds_topic_name("", topic).c_str(),
               ros2::default_qos()),
        reader_(dds::check(dds_create_reader(participant.handle(), topic_.handle(), dds::Qos::best_effort(10).get(),
                                             nullptr),
                           "dds_create_reader")),
        sensor_id(sensor) {}
  dds::Topic topic_;
  dds::Entity reader_;
  std::uint32_t sensor_id;
  std::uint64_t sequence = 0;
};

class Ros2PosePlugin {
 public:
  static constexpr std::array kParams = sdk::join(
      dds::kEndpointParams,
      std::array{sdk::text("base_topic", "/mocap/base/pose", "the ROS topic of the base's PoseStamped"),
                 sdk::integer("base_sensor_id", "", "0", "the sensor id of the base's samples", sdk::between(0, 31)),
                 sdk::text("head_topic", "/mocap/head/pose", "the ROS topic of the head's PoseStamped"),
                 sdk::integer("head_sensor_id", "", "1", "the sensor id of the head's samples", sdk::between(0, 31)),
                 sdk::text("frame_id", "mocap", "the frame_id the poses must carry: the tracker frame"),
                 sdk::number("max_position_m", "m", "20", "poses farther out, per coordinate, are refused",
                             sdk::above_up_to(0, 1000)),
                 sdk::number("max_age_s", "s", "0.1", "older poses are stale and refused", sdk::above_up_to(0, 10)),
                 sdk::number("max_future_s", "s", "0.01", "clock skew allowed for poses from the future",
                             sdk::between(0, 10))});

  Ros2PosePlugin(const mhd_host& host, const sdk::Params& params)
      : host_(host),
        endpoint_(dds::read_endpoint(params, host.scene_file)),
        participant_(endpoint_.domain_id, endpoint_.config, endpoint_.identity_dir),
        frame_id_(dds::checked_ros_name("frame_id", params.text("frame_id"))),
        roles_{RoleReader(participant_, dds::checked_ros_name("base_topic", params.text("base_topic")),
                          static_cast<std::uint32_t>(params.integer("base_sensor_id"))),
               RoleReader(participant_, dds::checked_ros_name("head_topic", params.text("head_topic")),
                          static_cast<std::uint32_t>(params.integer("head_sensor_id")))},
        validator_(limits(params, endpoint_.rig_id)) {
    if (roles_[0].sensor_id == roles_[1].sensor_id) {
      throw sdk::ParamError("parameters 'base_sensor_id' and 'head_sensor_id' must differ");
    }
  }

  /// The poses that passed since the last read, up to out.size().
  std::size_t tracker_read(std::span<mhd_tracker_sample> out) {
    std::size_t count = 0;
    for (RoleReader& role : roles_) count += take(role, out.subspan(count));
    return count;
  }

  std::size_t counters(std::span<mhd_counter> out) const {
    const dds::DropCounts& c = validator_.counts();
    for (std::size_t i = 0; i < kCounterNames.size() && i < out.size(); ++i) {
      std::uint64_t value = 0;
      if (i == 0) value = c.accepted;
      if (i == 1) value = wrong_frame_;
      if (i >= 2) value = c.dropped[i - 2];
      out[i] = {kCounterNames[i], value};
    }
    return kCounterNames.size();
  }

 private:
  static dds::TrackerValidationLimits limits(const sdk::Params& params, std::uint32_t rig_id) {
    dds::TrackerValidationLimits l;
    l.rig_id = rig_id;
    l.max_abs_position_m = params.number("max_position_m");
    l.max_age_s = params.number("max_age_s");
    l.max_future_s = params.number("max_future_s");
    return l;
  }

  /// Takes what `role`'s reader holds (loaned: the messages carry strings); the samples
  /// that pass go to `out` while it has room.
  std::size_t take(RoleReader& role, std::span<mhd_tracker_sample> out) {
    std::size_t count = 0;
    std::array<void*, 16> samples{};
    std::array<dds_sample_info_t, 16> infos{};
    const std::int64_t now_ns = dds::realtime_ns();
    const double host_now_s = sdk::host_now(host_);
    for (;;) {
      samples.fill(nullptr);  // null: Cyclone lends the samples
      const dds_return_t n = dds::check(dds_take(role.reader_.handle(), samples.data(), infos.data(), samples.size(),
                                                 static_cast<std::uint32_t>(samples.size())),
                                        "dds_take");
      for (dds_return_t i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (!infos[k].valid_data) continue;
        const auto& pose = *static_cast<const ros2::PoseStamped*>(samples[k]);
        const mhd_dds_TrackerSample sample = to_sample(role, pose);
        if (pose.header.frame_id == nullptr || frame_id_ != pose.header.frame_id) {
          ++wrong_frame_;
        } else if (!validator_.check(sample, now_ns) && count < out.size()) {
          out[count++] = dds::from_dds(sample, dds::host_from_realtime(sample.timestamp_ns, host_now_s, now_ns));
        }
      }
      if (n > 0) dds_return_loan(role.reader_.handle(), samples.data(), n);
      if (n < static_cast<dds_return_t>(samples.size())) break;
    }
    return count;
  }

  /// The pose as the `dds` tracker's sample type: this rig, the role's sensor, the next
  /// sequence number (ROS 2 has none), the stamp; ROS's (x, y, z, w) as (w, x, y, z).
  mhd_dds_TrackerSample to_sample(RoleReader& role, const ros2::PoseStamped& pose) const {
    mhd_dds_TrackerSample s{};
    s.rig_id = endpoint_.rig_id;
    s.sensor_id = role.sensor_id;
    s.sequence_number = ++role.sequence;
    s.timestamp_ns = ros2::stamp_ns(pose.header.stamp);
    s.p_T_m[0] = pose.pose.position.x;
    s.p_T_m[1] = pose.pose.position.y;
    s.p_T_m[2] = pose.pose.position.z;
    s.q_T_wxyz[0] = pose.pose.orientation.w;
    s.q_T_wxyz[1] = pose.pose.orientation.x;
    s.q_T_wxyz[2] = pose.pose.orientation.y;
    s.q_T_wxyz[3] = pose.pose.orientation.z;
    return s;
  }

  mhd_host host_;
  dds::DdsEndpoint endpoint_;
  dds::Participant participant_;
  std::string frame_id_;
  std::array<RoleReader, 2> roles_;
  dds::TrackerSampleValidator validator_;
  std::uint64_t wrong_frame_ = 0;
};

}  // namespace mhd::ros2_pose

MHD_PLUGIN_ENTRY(mhd::ros2_pose::Ros2PosePlugin,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "Base and head poses from a ROS 2 motion-capture driver (PoseStamped) over Cyclone DDS"})
