// ROS 2 interop without ROS: the haptic server of dds_server_test's
// pipeline (a tracker server process replaying the base's approach into a wall, the
// server in this process) with the `ros2_state` display, and a plain Cyclone subscriber
// on its own participant that knows only ROS 2's topic and type names
// ("rt/mhd/rig44/hip_pose", "geometry_msgs::msg::dds_::PoseStamped_", ...), as
// `ros2 topic echo` on rmw_cyclonedds would. What it receives is checked against the run.
#include "dds_server_support.h"
#include "dds_test_support.h"

#include "dds_common/ros2_messages.h"
#include "dds_common/ros2_topics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace mhd;
using namespace mhd::dds_server_test;
namespace ros2 = mhd::dds::ros2;
using mhd::dds::test::ChildProcess;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr std::uint32_t kRos2Rig = 44;  // dds_server_test.cpp uses 41 to 43

std::int64_t stamp_ns(const ros2::Time& t) { return std::int64_t{t.sec} * 1'000'000'000 + t.nanosec; }

/// What the subscriber keeps of one sample: stamp, frame and values.
struct Received {
  std::int64_t stamp_ns = 0;
  std::string frame_id;
  std::array<double, 7> values{};  ///< pose: x y z qx qy qz qw; wrench: force, torque
  std::vector<std::string> names;  ///< joint_states
};

Received received(const ros2::PoseStamped& m) {
  const auto& p = m.pose;
  return {stamp_ns(m.header.stamp), m.header.frame_id,
          {p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y, p.orientation.z,
           p.orientation.w},
          {}};
}
Received received(const ros2::WrenchStamped& m) {
  const auto& w = m.wrench;
  return {stamp_ns(m.header.stamp), m.header.frame_id,
          {w.force.x, w.force.y, w.force.z, w.torque.x, w.torque.y, w.torque.z, 0.0},
          {}};
}
Received received(const ros2::JointState& m) {
  Received r{stamp_ns(m.header.stamp), m.header.frame_id, {}, {}};
  for (std::uint32_t i = 0; i < m.name._length; ++i) r.names.emplace_back(m.name._buffer[i]);
  for (std::uint32_t i = 0; i < m.position._length && i < r.values.size(); ++i) r.values[i] = m.position._buffer[i];
  return r;
}

/// A reader of one ROS 2 topic, by its DDS name and type descriptor only. Takes loans:
/// JointState holds sequences that Cyclone allocates.
template <class T>
class RosReader {
 public:
  RosReader(const dds::Participant& participant, const dds_topic_descriptor_t& type, const std::string& name,
            bool best_effort)
      : topic_(participant, type, name.c_str(), ros2::default_qos()),
        reader_(dds::check(dds_create_reader(participant.handle(), topic_.handle(),
                                             (best_effort ? dds::Qos::best_effort(10) : ros2::default_qos()).get(),
                                             nullptr),
                           "dds_create_reader")) {}
  void take_into(std::vector<Received>& out) {
    std::array<void*, 32> samples{};
    std::array<dds_sample_info_t, 32> infos{};
    const dds_return_t n = dds_take(reader_.handle(), samples.data(), infos.data(), samples.size(), samples.size());
    dds::check(n, "dds_take");
    for (dds_return_t i = 0; i < n; ++i) {
      if (infos[i].valid_data) out.push_back(received(*static_cast<const T*>(samples[i])));
    }
    if (n > 0) dds::check(dds_return_loan(reader_.handle(), samples.data(), n), "dds_return_loan");
  }

 private:
  dds::Topic topic_;
  dds::Entity reader_;
};

double norm(const Received& r) { return std::hypot(r.values[0], r.values[1], r.values[2]); }

TEST(Ros2Interop, PlainCycloneSubscriberWithRos2NamesReceivesTheRigsPosesWrenchAndJointStates) {
  const fs::path dir = fs::path(::testing::TempDir()) / "dds_server_test" / "ros2_interop";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::uint32_t domain = dds::test::use_loopback_and_unique_domain(12);
  const Rig rig = thesis_rig();
  write_approach_replay(dir / "approach.csv", rig, 30.0, 0.6, 0.03, 0.1);
  const fs::path tracker_scene = write_tracker_scene(dir, dir / "approach.csv");
  SceneOptions o;
  o.domain_id = domain;
  o.rig_id = kRos2Rig;
  o.base_log = dir / "base.log";
  o.state_display = false;
  o.ros2_display = true;
  const LoadedScene scene = load_scene(write_server_scene(dir, o));
  ASSERT_TRUE(scene.compiled) << (scene.errors.empty() ? "" : scene.errors.front());

  const dds::Participant participant(domain);
  const std::string ns = "mhd/rig" + std::to_string(kRos2Rig);
  auto name = [&](const char* topic) { return "rt/" + ns + "/" + topic; };
  // Best-effort for one pose (rviz2's sensor-data profile), ROS's reliable default for the rest.
  RosReader<ros2::PoseStamped> hip_reader(participant, geometry_msgs_msg_dds__PoseStamped__desc, name("hip_pose"), true);
  RosReader<ros2::PoseStamped> proxy_reader(participant, geometry_msgs_msg_dds__PoseStamped__desc, name("proxy_pose"), false);
  RosReader<ros2::PoseStamped> base_reader(participant, geometry_msgs_msg_dds__PoseStamped__desc, name("base_pose"), false);
  RosReader<ros2::PoseStamped> head_reader(participant, geometry_msgs_msg_dds__PoseStamped__desc, name("head_pose"), false);
  RosReader<ros2::WrenchStamped> force_reader(participant, geometry_msgs_msg_dds__WrenchStamped__desc, name("force"), false);
  RosReader<ros2::JointState> joint_reader(participant, sensor_msgs_msg_dds__JointState__desc, name("joint_states"), false);

  const std::int64_t run_start_ns = dds::realtime_ns();
  ServerOptions options;
  options.plugin_path = plugin_dirs();
  ServerThread server(scene, options);
  ASSERT_TRUE(server.opened()) << server.errors().front();
  ChildProcess tracker(tracker_server_args(tracker_scene, domain, kRos2Rig, 30.0), (dir / "tracker.log").string());

  // Until the hand has pushed into the wall for 20 frames.
  std::vector<Received> hip, proxy, base, head, force, joints;
  const auto end = Clock::now() + std::chrono::seconds(10);
  auto pushing = [&] {
    return std::count_if(force.begin(), force.end(), [](const Received& r) { return norm(r) > 1.0; });
  };
  while (Clock::now() < end && pushing() < 20) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    hip_reader.take_into(hip);
    proxy_reader.take_into(proxy);
    base_reader.take_into(base);
    head_reader.take_into(head);
    force_reader.take_into(force);
    joint_reader.take_into(joints);
  }
  const ServerReport report = server.stop();
  const std::int64_t run_end_ns = dds::realtime_ns();
  EXPECT_FALSE(report.error) << *report.error;
  ASSERT_GE(pushing(), 20) << "wrenches: " << force.size() << "\n" << dds::test::read_file((dir / "tracker.log").string());
  ASSERT_GT(report.contact_ticks, 0u);

  // Every topic: MHD's world frame (JointState names joints, no frame), stamps
  // increasing and inside the run.
  for (const auto* topic : {&hip, &proxy, &base, &head, &force, &joints}) {
    ASSERT_GT(topic->size(), 10u);
    for (std::size_t i = 0; i < topic->size(); ++i) {
      const Received& r = (*topic)[i];
      EXPECT_EQ(r.frame_id, topic == &joints ? "" : ros2::kDefaultFrameId);
      EXPECT_GE(r.stamp_ns, run_start_ns);
      EXPECT_LE(r.stamp_ns, run_end_ns);
      if (i > 0) {
        EXPECT_GT(r.stamp_ns, (*topic)[i - 1].stamp_ns) << "sample " << i;
      }
    }
  }
  // Never more than the clamp; torque zero; in the wall k * depth pushing the hand back (-x).
  // The scene's clamp, or sim_phantom's own limit (the same as the no-device one) when it gives none.
  const double clamp_N = scene.description->haptics.max_force_N.value_or(kNoDeviceMaxForce_N);
  for (const Received& r : force) {
    EXPECT_LE(norm(r), clamp_N + 1e-9);
    EXPECT_EQ(r.values[3], 0.0);
    EXPECT_EQ(r.values[4], 0.0);
    EXPECT_EQ(r.values[5], 0.0);
  }
  const double expected_force_N = kWallStiffness_N_per_m * kWallPenetration_m;
  EXPECT_NEAR(norm(force.back()), expected_force_N, 0.2 * expected_force_N);
  EXPECT_LT(force.back().values[0], -0.9 * norm(force.back()));

  // The HIP where the rig puts it with the base at the origin, the proxy on the wall's face.
  const Eigen::Vector3d p_W_hip = hip_at(rig, BasePose{});
  EXPECT_NEAR(hip.back().values[0], p_W_hip.x(), 1e-3);
  EXPECT_NEAR(hip.back().values[1], p_W_hip.y(), 1e-3);
  EXPECT_NEAR(hip.back().values[2], p_W_hip.z(), 1e-3);
  EXPECT_EQ(hip.back().values[6], 1.0);  // a point: orientation identity
  EXPECT_NEAR(proxy.back().values[0], p_W_hip.x() - kWallPenetration_m, 1e-4);
  // The head of the replay's user standing at (-3, 1.7, 0), its sensor unrotated in the
  // tracker's frame T, so turned as T is in W.
  EXPECT_NEAR(head.back().values[0], -3.0, 1e-3);
  EXPECT_NEAR(head.back().values[1], 1.7, 1e-3);
  const Eigen::Quaterniond q_W_T(rig.X_W_is900().rotation());
  EXPECT_NEAR(std::abs(head.back().values[3] * q_W_T.x() + head.back().values[4] * q_W_T.y() +
                       head.back().values[5] * q_W_T.z() + head.back().values[6] * q_W_T.w()),
              1.0, 1e-6);

  // The base: seen 30 mm behind the origin on the approach, then at the origin, heading 0.
  EXPECT_TRUE(std::any_of(base.begin(), base.end(), [](const Received& r) { return r.values[0] < -0.01; }));
  EXPECT_NEAR(base.back().values[0], 0.0, 1e-3);
  EXPECT_EQ(base.back().values[1], 0.0);
  EXPECT_NEAR(base.back().values[6], 1.0, 1e-6);
  // JointState: the base's planar joints, equal to base_pose of the same frame.
  std::map<std::int64_t, const Received*> base_at;
  for (const Received& r : base) base_at[r.stamp_ns] = &r;
  std::size_t matched = 0;
  for (const Received& j : joints) {
    ASSERT_EQ(j.names, (std::vector<std::string>{"base_x", "base_z", "base_heading"}));
    const auto b = base_at.find(j.stamp_ns);
    if (b == base_at.end()) continue;
    ++matched;
    EXPECT_EQ(j.values[0], b->second->values[0]);
    EXPECT_EQ(j.values[1], b->second->values[2]);
    EXPECT_NEAR(j.values[2], 2.0 * std::atan2(b->second->values[4], b->second->values[6]), 1e-12);
  }
  EXPECT_GT(matched, joints.size() / 2);
}

TEST(Ros2Interop, Ros2WritersUsePlainCdrAsRmwCycloneddsDoes) {
  // rmw_cyclonedds reads XCDR1 ("CDR_LE"); Cyclone would pick XCDR2 for types that need it.
  const std::uint32_t domain = dds::test::use_loopback_and_unique_domain(13);
  const dds::Participant participant(domain);
  ros2::RosPublisher<ros2::JointState> publisher(participant, sensor_msgs_msg_dds__JointState__desc,
                                                 "rt/mhd/test/joint_states");
  dds::Qos qos;
  dds::check(dds_get_qos(publisher.writer().handle(), qos.get_mutable()), "dds_get_qos");
  uint32_t n = 0;
  dds_data_representation_id_t* ids = nullptr;
  ASSERT_TRUE(dds_qget_data_representation(qos.get(), &n, &ids));
  ASSERT_GE(n, 1u);
  EXPECT_EQ(ids[0], DDS_DATA_REPRESENTATION_XCDR1);
  dds_free(ids);
}

}  // namespace
