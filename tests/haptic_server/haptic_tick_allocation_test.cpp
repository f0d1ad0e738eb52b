// The haptic tick allocates nothing: a tick runs on the 1 kHz thread.
#include "haptic_server/haptic_tick.h"

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "support/allocation_counter.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace mhd;

TEST(HapticTickAllocation, TicksInAndOutOfContactAllocateNothing) {
  auto read = read_scene_file(std::string(MHD_SOURCE_DIR) + "/scenes/dolphin.xml");
  ASSERT_TRUE(read.ok());
  auto compiled = compile_scene(*read);
  ASSERT_TRUE(compiled.ok());
  const Rig rig = Rig::from_scene(*read).value();
  // What a Cartesian PHANToM reports for joint angles q (ABI 3): its tool in the device frame.
  const auto tool = [&rig](const Eigen::Vector3d& q_rad) { return phantom_tool_position(rig.device().geometry, q_rad); };
  HapticTick tick(*compiled.value(), rig, HapticTickSettings{});
  const BasePose base{0.0, -0.926, 0.0};  // as the dolphin scene places it
  const Pose sensor = rig.X_is900_base_sensor_from_base(base);
  double t = 0.0;
  Eigen::Vector3d q(0.0, 0.9, 0.2);  // the HIP above the dolphin's back
  (void)tick.add_base_sensor_sample(t, sensor);
  for (int i = 0; i < 100; ++i) (void)tick.tick(t += 0.001, 0.001, tool(q));  // warm up

  test::AllocationCounter counter;  // tool() (forward kinematics, fixed-size Eigen) allocates nothing either
  int contact_ticks = 0;
  for (int i = 0; i < 3000; ++i) {
    t += 0.001;
    if (i % 10 == 0) (void)tick.add_base_sensor_sample(t - 0.004, sensor);
    q.y() = 0.65 + 0.25 * std::cos(0.003 * i);  // the arm goes down into the dolphin's back and up
    const auto out = tick.tick(t, 0.001, tool(q));
    if (out.in_contact) ++contact_ticks;
  }
  counter.stop();
  EXPECT_EQ(counter.count(), 0);
  EXPECT_GT(contact_ticks, 0);
}

}  // namespace
