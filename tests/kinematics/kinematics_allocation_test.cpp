// The rig's per-tick functions run in the 1 kHz haptic thread: they must not allocate.
// Counted with test::AllocationCounter (its own binary: it replaces operator new).

#include "kinematics/rig.h"

#include "scene_xml/scene_reader.h"

#include "support/allocation_counter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace mhd {
namespace {

TEST(KinematicsAllocation, PerTickRigFunctionsAllocateNothing) {
  const Result<SceneDescription> read = read_scene_file(std::filesystem::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml");
  ASSERT_TRUE(read.ok());
  const Result<Rig, std::vector<RigError>> built = Rig::from_scene(*read);
  ASSERT_TRUE(built.ok());
  const Rig& rig = *built;

  test::AllocationCounter allocations;
  double sum = 0;
  for (int i = 0; i < 3000; ++i) {
    const double t = 0.001 * i;
    const BasePose base{0.2 * t, 0.1 * std::sin(t), 0.7 * t};
    const Eigen::Vector3d q(0.3 * std::sin(t), 0.2 + 0.1 * std::cos(t), 0.3 * std::sin(2 * t));
    const Pose X_is900_sensor = rig.X_is900_base_sensor_from_base(base);
    const Pose X_W_robot = rig.X_W_robot_from_sensor(X_is900_sensor);
    const BasePose back = rig.base_from_sensor(X_is900_sensor);
    const Eigen::Vector3d p_W = rig.p_W_hip(rig.X_W_robot_from_base(back), q);
    const Pose X_W_tool = rig.X_W_tool(X_W_robot, q);
    const Eigen::Vector3d tau = rig.joint_torques_Nm(X_W_robot, q, Eigen::Vector3d(0, -1, 0.5));
    const Rig::HipJacobian J = rig.hip_jacobian(base, q);
    const PhantomIkSolution ik = phantom_inverse_kinematics(rig.device(), rig.p_P_from_W(X_W_robot, p_W));
    sum += p_W.sum() + X_W_tool.translation().sum() + tau.sum() + J.sum() + ik.q_rad.sum();
  }
  allocations.stop();
  EXPECT_TRUE(std::isfinite(sum));
  EXPECT_EQ(allocations.count(), 0);
}

}  // namespace
}  // namespace mhd
