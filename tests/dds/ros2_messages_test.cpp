// The ROS 2 messages of dds_common (ros2_msgs.idl, ros2_messages.h), without a network:
// ROS 2's type and topic names, the conversions from a display frame, and the bytes on
// the wire, compared with plain CDR (XCDR1, what rmw_cyclonedds reads) laid out by hand
// from the .msg definitions.

#include "dds_common/ros2_messages.h"

#include <dds/ddsi/ddsi_cdrstream.h>
#include <dds/ddsi/q_protocol.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace mhd::dds::ros2 {
namespace {

TEST(Ros2Messages, TypeNamesAreRos2sDdsNames) {
  EXPECT_STREQ(geometry_msgs_msg_dds__PoseStamped__desc.m_typename, "geometry_msgs::msg::dds_::PoseStamped_");
  EXPECT_STREQ(geometry_msgs_msg_dds__WrenchStamped__desc.m_typename, "geometry_msgs::msg::dds_::WrenchStamped_");
  EXPECT_STREQ(sensor_msgs_msg_dds__JointState__desc.m_typename, "sensor_msgs::msg::dds_::JointState_");
  // ROS 2 topics have no key: a keyed type would not match ROS's keyless endpoints.
  EXPECT_EQ(geometry_msgs_msg_dds__PoseStamped__desc.m_nkeys, 0u);
  EXPECT_EQ(geometry_msgs_msg_dds__WrenchStamped__desc.m_nkeys, 0u);
  EXPECT_EQ(sensor_msgs_msg_dds__JointState__desc.m_nkeys, 0u);
}

TEST(Ros2Messages, TopicNamesTakeRos2sRtPrefix) {
  EXPECT_EQ(default_namespace(3), "mhd/rig3");
  EXPECT_EQ(dds_topic_name(default_namespace(1), "hip_pose"), "rt/mhd/rig1/hip_pose");
  EXPECT_EQ(dds_topic_name("/lab/", "/force"), "rt/lab/force");
  EXPECT_EQ(dds_topic_name("", "joint_states"), "rt/joint_states");
}

TEST(Ros2Messages, TimeSplitsIntoSecondsAndNanoseconds) {
  const Time t = ros_time(1'700'000'000'123'456'789);
  EXPECT_EQ(t.sec, 1'700'000'000);
  EXPECT_EQ(t.nanosec, 123'456'789u);
  const Time before_epoch = ros_time(-1);
  EXPECT_EQ(before_epoch.sec, -1);
  EXPECT_EQ(before_epoch.nanosec, 999'999'999u);
}

/// v rotated by the unit quaternion q.
std::array<double, 3> rotate(const Quaternion& q, const std::array<double, 3>& v) {
  // v' = v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
  const std::array<double, 3> u{q.x, q.y, q.z};
  auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const auto uv = cross(u, v);
  const auto uuv = cross(u, uv);
  return {v[0] + 2 * (q.w * uv[0] + uuv[0]), v[1] + 2 * (q.w * uv[1] + uuv[1]), v[2] + 2 * (q.w * uv[2] + uuv[2])};
}

mhd_display_frame sample_frame() {
  mhd_display_frame f{};
  f.timestamp_s = 12.0;
  f.p_W_hip_m[0] = 0.1, f.p_W_hip_m[1] = 1.0, f.p_W_hip_m[2] = -0.3;
  f.p_W_proxy_m[0] = 0.1, f.p_W_proxy_m[1] = 0.99, f.p_W_proxy_m[2] = -0.3;
  f.force_W_N[0] = 0.5, f.force_W_N[1] = 2.0, f.force_W_N[2] = -0.25;
  f.in_contact = 1;
  f.base_x_m = -0.4, f.base_z_m = 0.2, f.base_heading_rad = 0.7;
  f.p_W_head_m[0] = 0.0, f.p_W_head_m[1] = 1.65, f.p_W_head_m[2] = 0.5;
  // 90 degrees about +y: w = cos 45, y = sin 45.
  f.q_W_head_wxyz[0] = std::sqrt(0.5), f.q_W_head_wxyz[2] = std::sqrt(0.5);
  return f;
}

TEST(Ros2Messages, RigMessagesCarryTheFrameInRosConventions) {
  RigMessages m("mhd_world");
  m.set(sample_frame(), 5'000'000'250);
  for (const PoseStamped* p : {&m.hip, &m.proxy, &m.base, &m.head}) {
    EXPECT_STREQ(p->header.frame_id, "mhd_world");
    EXPECT_EQ(p->header.stamp.sec, 5);
    EXPECT_EQ(p->header.stamp.nanosec, 250u);
  }
  EXPECT_STREQ(m.force.header.frame_id, "mhd_world");
  EXPECT_EQ(m.joints.header.stamp.sec, 5);

  EXPECT_DOUBLE_EQ(m.hip.pose.position.z, -0.3);
  EXPECT_DOUBLE_EQ(m.hip.pose.orientation.w, 1.0);
  EXPECT_DOUBLE_EQ(m.proxy.pose.position.y, 0.99);
  // The head's (w, x, y, z) becomes ROS's (x, y, z, w).
  EXPECT_DOUBLE_EQ(m.head.pose.orientation.x, 0.0);
  EXPECT_DOUBLE_EQ(m.head.pose.orientation.y, std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(m.head.pose.orientation.w, std::sqrt(0.5));
  // The base on the floor, facing (cos h, 0, -sin h) (docs/simulation.md, "Conventions").
  EXPECT_DOUBLE_EQ(m.base.pose.position.x, -0.4);
  EXPECT_DOUBLE_EQ(m.base.pose.position.y, 0.0);
  EXPECT_DOUBLE_EQ(m.base.pose.position.z, 0.2);
  const auto forward = rotate(m.base.pose.orientation, {1.0, 0.0, 0.0});
  EXPECT_NEAR(forward[0], std::cos(0.7), 1e-12);
  EXPECT_NEAR(forward[1], 0.0, 1e-12);
  EXPECT_NEAR(forward[2], -std::sin(0.7), 1e-12);

  EXPECT_DOUBLE_EQ(m.force.wrench.force.x, 0.5);
  EXPECT_DOUBLE_EQ(m.force.wrench.force.y, 2.0);
  EXPECT_DOUBLE_EQ(m.force.wrench.force.z, -0.25);
  EXPECT_DOUBLE_EQ(m.force.wrench.torque.x, 0.0);

  ASSERT_EQ(m.joints.name._length, 3u);
  ASSERT_EQ(m.joints.position._length, 3u);
  EXPECT_STREQ(m.joints.name._buffer[0], "base_x");
  EXPECT_STREQ(m.joints.name._buffer[1], "base_z");
  EXPECT_STREQ(m.joints.name._buffer[2], "base_heading");
  EXPECT_DOUBLE_EQ(m.joints.position._buffer[0], -0.4);
  EXPECT_DOUBLE_EQ(m.joints.position._buffer[1], 0.2);
  EXPECT_DOUBLE_EQ(m.joints.position._buffer[2], 0.7);
  EXPECT_EQ(m.joints.velocity._length, 0u);
  EXPECT_EQ(m.joints.effort._length, 0u);
}

/// Plain CDR, little-endian, as the OMG CDR rules and ROS 2's .msg definitions give it:
/// each primitive aligned to its size from the start of the payload, a string as its
/// length with the NUL and its bytes, a sequence as its length and its elements.
class Cdr {
 public:
  Cdr& i32(std::int32_t v) { return put(v); }
  Cdr& u32(std::uint32_t v) { return put(v); }
  Cdr& f64(double v) { return put(v); }
  Cdr& str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size() + 1));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    bytes_.push_back(0);
    return *this;
  }
  Cdr& header(std::int32_t sec, std::uint32_t nanosec, const std::string& frame_id) {
    return i32(sec).u32(nanosec).str(frame_id);
  }
  [[nodiscard]] const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  template <class T>
  Cdr& put(T v) {
    while (bytes_.size() % sizeof(T) != 0) bytes_.push_back(0);
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));  // x86-64: little-endian, as rmw_cyclonedds writes there
    bytes_.insert(bytes_.end(), raw, raw + sizeof(T));
    return *this;
  }
  std::vector<unsigned char> bytes_;
};

/// What Cyclone puts on the wire for `sample` in XCDR1, less the 4-byte encapsulation header.
std::vector<unsigned char> cyclone_cdr(const dds_topic_descriptor_t& type, const void* sample) {
  dds_ostream_t os;
  dds_ostream_init(&os, 0, CDR_ENC_VERSION_1);
  (void)dds_stream_write(&os, static_cast<const char*>(sample), type.m_ops);
  std::vector<unsigned char> out(os.m_buffer, os.m_buffer + os.m_index);
  dds_ostream_fini(&os);
  return out;
}

TEST(Ros2Messages, PoseStampedAndWrenchStampedHaveRos2sWireLayout) {
  RigMessages m("mhd_world");
  const mhd_display_frame f = sample_frame();
  m.set(f, 5'000'000'250);
  const double h = std::sqrt(0.5);
  const auto head = Cdr().header(5, 250, "mhd_world")
                        .f64(0.0).f64(1.65).f64(0.5)   // position x, y, z
                        .f64(0.0).f64(h).f64(0.0).f64(h)  // orientation x, y, z, w
                        .bytes();
  EXPECT_EQ(cyclone_cdr(geometry_msgs_msg_dds__PoseStamped__desc, &m.head), head);
  const auto force = Cdr().header(5, 250, "mhd_world")
                         .f64(0.5).f64(2.0).f64(-0.25)  // force
                         .f64(0.0).f64(0.0).f64(0.0)    // torque
                         .bytes();
  EXPECT_EQ(cyclone_cdr(geometry_msgs_msg_dds__WrenchStamped__desc, &m.force), force);
}

TEST(Ros2Messages, JointStateHasRos2sWireLayout) {
  RigMessages m("mhd_world");
  m.set(sample_frame(), 5'000'000'250);
  const auto joints = Cdr().header(5, 250, "")
                          .u32(3).str("base_x").str("base_z").str("base_heading")
                          .u32(3).f64(-0.4).f64(0.2).f64(0.7)
                          .u32(0)   // velocity
                          .u32(0)   // effort
                          .bytes();
  EXPECT_EQ(cyclone_cdr(sensor_msgs_msg_dds__JointState__desc, &m.joints), joints);
}

}  // namespace
}  // namespace mhd::dds::ros2
