// The openhaptics plugin's joint states, as a ROS 2 display (rviz2, `ros2 topic echo`) on
// rmw_cyclonedds would see them: a plain Cyclone DDS reader of sensor_msgs/msg/JointState
// on the topic the scene names, while `mhd run` drives the fake libHD
// (fakes/fake_hd.cpp: its joint angles are 10 rad per metre of the tool's position, its
// gimbal angles 0.1, 0.2 and 0.3 rad).
#include "dds_common/dds_entity.h"
#include "dds_common/ros2_messages.h"
#include "dds_common/ros2_topics.h"
#include "dds_test_support.h"
#include "support/mhd_run_process.h"
#include "support/scratch_dir.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace ros2 = mhd::dds::ros2;

struct Received {
  std::vector<std::string> names;
  std::vector<double> positions_rad;
  std::int64_t stamp_ns = 0;
};

/// A display's reader of "/touch/joint_states": keeps what it takes (loaned: the messages
/// carry strings and sequences).
class JointStateDisplay {
 public:
  explicit JointStateDisplay(std::uint32_t domain)
      : participant_(domain),
        topic_(participant_, sensor_msgs_msg_dds__JointState__desc, "rt/touch/joint_states", ros2::default_qos()),
        reader_(mhd::dds::check(
            dds_create_reader(participant_.handle(), topic_.handle(), ros2::default_qos().get(), nullptr),
            "dds_create_reader")) {}

  void receive() {
    std::array<void*, 16> samples{};
    std::array<dds_sample_info_t, 16> infos{};
    for (;;) {
      samples.fill(nullptr);
      const dds_return_t n = dds_take(reader_.handle(), samples.data(), infos.data(), samples.size(),
                                      static_cast<std::uint32_t>(samples.size()));
      ASSERT_GE(n, 0);
      for (dds_return_t i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (!infos[k].valid_data) continue;
        const auto& m = *static_cast<const ros2::JointState*>(samples[k]);
        Received r;
        for (std::uint32_t j = 0; j < m.name._length; ++j) r.names.emplace_back(m.name._buffer[j]);
        r.positions_rad.assign(m.position._buffer, m.position._buffer + m.position._length);
        r.stamp_ns = ros2::stamp_ns(m.header.stamp);
        received_.push_back(r);
      }
      if (n > 0) dds_return_loan(reader_.handle(), samples.data(), n);
      if (n < static_cast<dds_return_t>(samples.size())) break;
    }
  }
  [[nodiscard]] const std::vector<Received>& received() const { return received_; }

 private:
  mhd::dds::Participant participant_;
  mhd::dds::Topic topic_;
  mhd::dds::Entity reader_;
  std::vector<Received> received_;
};

/// `mhd run` for 2 s of the desk scene with the fake libHD; the display reads meanwhile.
std::vector<Received> run_and_watch(const std::string& name, const std::string& device_params,
                                    std::uint32_t domain, std::string& output) {
  const fs::path dir = mhd::test::scratch_dir("arm_joints", name);
  std::ofstream(dir / "scene.xml") << mhd::test::fill_scene_template(
      fs::path(MHD_SOURCE_DIR) / "tests/data/hardware/vendor_desk.xml", {{"<!--DEVICE-->", device_params}});
  JointStateDisplay display(domain);
  mhd::test::MhdRunProcess mhd({.argv = {MHD_CLI, "run", (dir / "scene.xml").string(), "--duration", "2", "-q"},
                                .dir = dir,
                                .env = {{"LD_LIBRARY_PATH", MHD_FAKE_HD_DIR}}});
  std::optional<int> status;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!status && std::chrono::steady_clock::now() < give_up) {
    display.receive();
    status = mhd.wait_for(std::chrono::milliseconds(20));
  }
  display.receive();
  output = mhd.output();
  EXPECT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << output;
  return display.received();
}

TEST(ArmJointState, TheArmsJointsReachADisplayAsTheDriverReadThem) {
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(21);
  std::string output;
  const auto received = run_and_watch(
      "published",
      "<param name=\"joint_state_topic\" value=\"/touch/joint_states\"/>"
      "<param name=\"domain_id\" value=\"" + std::to_string(domain) + "\"/>",
      domain, output);
  // 100 Hz for about 2 s, less discovery.
  ASSERT_GT(received.size(), 100u) << output;
  const std::vector<std::string> names{"waist", "shoulder", "elbow", "wrist1", "wrist2", "wrist3"};
  double lowest_shoulder = 1e9;
  double highest_shoulder = -1e9;
  for (const Received& r : received) {
    ASSERT_EQ(r.names, names);
    ASSERT_EQ(r.positions_rad.size(), 6u);
    EXPECT_EQ(r.positions_rad[3], 0.1);
    EXPECT_EQ(r.positions_rad[4], 0.2);
    EXPECT_EQ(r.positions_rad[5], 0.3);
    lowest_shoulder = std::min(lowest_shoulder, r.positions_rad[1]);
    highest_shoulder = std::max(highest_shoulder, r.positions_rad[1]);
  }
  // The fake's hand moves 50 mm up and down: 0.5 rad of its stand-in shoulder.
  EXPECT_GT(highest_shoulder - lowest_shoulder, 0.3);
  for (std::size_t i = 1; i < received.size(); ++i) EXPECT_GT(received[i].stamp_ns, received[i - 1].stamp_ns);
  const std::int64_t age_ns = mhd::dds::realtime_ns() - received.back().stamp_ns;
  EXPECT_LT(age_ns, 30'000'000'000) << "stamped on another clock";
}

TEST(ArmJointState, NothingIsPublishedWithoutATopic) {
  const std::uint32_t domain = mhd::dds::test::use_loopback_and_unique_domain(22);
  std::string output;
  const auto received =
      run_and_watch("unpublished", "<param name=\"domain_id\" value=\"" + std::to_string(domain) + "\"/>", domain, output);
  EXPECT_TRUE(received.empty()) << received.size() << " messages\n" << output;
}

}  // namespace
