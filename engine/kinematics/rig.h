#pragma once
// The mobile haptic display's kinematic chain (thesis ch. 4.1-4.3), world to tool:
//
//   world -> is900 -> base_sensor -> robot -> phantom -> tool
//                     (measured)              (joint angles)
//
// Fixed transforms come from the scene's <rig> frames; the base_sensor pose comes from
// the IS-900 tracker and the tool pose from the device's joint angles. For the haptic
// server, which tracks the base as a planar pose (x, z, heading), a fifth frame, "base",
// is the floor point under the robot: world -> base (planar pose) -> robot -> phantom.
//
// Required frames (names and parents; any other frame, e.g. a head sensor, is ignored):
//   is900        parent world        the tracker's frame (thesis eq. 4.1)
//   base_sensor  parent is900        the tracker station on the robot; its pose in the
//                                    file is a nominal one, replaced by measurements
//   robot        parent base_sensor  the robot body (eq. 4.3): x forward, z up
//   phantom      parent robot        the device frame P (eq. 4.4), see phantom_kinematics.h
//   base         parent robot        on the floor under the robot: y up, x = the robot's
//                                    x, z = x cross y; the frame of BasePose
// With base_sensor at its nominal pose, base must be level and on the floor (y = 0):
// that ties the tracker path and the planar path together and catches axis mistakes.
// scenes/rigs/pomhi.xml holds the thesis's rig; docs/kinematics.md derives it.
//
// A lift (scene <rig><lift range=... max_speed=... max_acceleration=.../>) is a prismatic
// joint between robot and phantom along the robot's z, which must be vertical: at height
// h the arm's frame is X_robot_phantom(h) = Translation(0, 0, h) X_robot_phantom(0), the
// file's "phantom" frame being height 0. Functions that place the arm take the height
// (lift_m, default 0: a rig without a lift is one whose lift stays at 0).
//
// A desktop rig (scene <rig kind="desktop">, docs/desktop.md) has no tracker and no base:
// the device frame D (here called phantom, whatever the device) is fixed in the world at the
// scene's frame "device", X_WD. Rig::desktop() makes it a chain whose base stands at the
// world origin for ever (BasePose{}) and whose robot frame is the world, so every
// function below works unchanged with BasePose{}.
//
// Per-tick functions are noexcept, use fixed-size Eigen types and never allocate.

#include "geometry/pose.h"
#include "kinematics/base_pose.h"
#include "kinematics/phantom_kinematics.h"
#include "diagnostics/result.h"
#include "scene/scene_description.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mhd {

namespace rig_frame {
inline constexpr std::string_view kIs900 = "is900";
inline constexpr std::string_view kBaseSensor = "base_sensor";
inline constexpr std::string_view kRobot = "robot";
inline constexpr std::string_view kPhantom = "phantom";
inline constexpr std::string_view kBase = "base";
}  // namespace rig_frame

enum class RigErrorKind {
  MissingFrame,    ///< a required frame is not defined
  DuplicateFrame,  ///< a required frame is defined twice (the reader forbids it; lists built in code may not)
  WrongParent,     ///< a required frame hangs from another parent than the chain needs
  BaseNotLevel,    ///< base's y axis is not world up (with base_sensor at its nominal pose)
  BaseNotOnFloor,  ///< base is not at y = 0 (likewise)
  LiftNotVertical, ///< the lift's axis, the robot's z, is not world up (with base_sensor at its nominal pose)
  LiftOnDesktop,   ///< a desktop rig has no base to carry a lift
};

/// The rig's lift, in SI units (scene/scene_description.h's LiftDescription, checked).
struct Lift {
  double min_m = 0.0;
  double max_m = 0.0;
  double max_speed_mps = 0.0;
  double max_acceleration_mps2 = 0.0;
};

struct RigError {
  RigErrorKind kind = RigErrorKind::MissingFrame;
  std::string frame;    ///< the frame concerned
  std::string message;  ///< e.g. "rig frame 'robot' must have parent 'base_sensor', not 'is900'"
  SourceLocation where;  ///< the frame's definition; empty file for a missing frame

  /// "file:line: error: message", or "error: message" without a file.
  [[nodiscard]] std::string to_string() const;
};

/// Columns of Rig::hip_jacobian: base translation in the world (x, y, z), base heading,
/// then the device's joints (thesis eq. 5.1; eq. 5.2 drops the y column).
enum RigJacobianColumn : int { kBaseX = 0, kBaseY, kBaseZ, kBaseHeading, kTheta1, kTheta2, kTheta3 };

class Rig {
 public:
  using HipJacobian = Eigen::Matrix<double, 3, 7>;

  /// Builds the rig from the scene's frames; every problem is reported, not only the first.
  [[nodiscard]] static Result<Rig, std::vector<RigError>> from_frames(const std::vector<FrameDescription>& frames,
                                                  const PhantomModel& device = phantom_premium_1_5());
  /// A mobile scene's frames through from_frames(), then its lift (range, limits and a
  /// vertical axis); a desktop scene's "device" frame through desktop(), refusing a lift.
  [[nodiscard]] static Result<Rig, std::vector<RigError>> from_scene(const SceneDescription& scene,
                                                 const PhantomModel& device = phantom_premium_1_5());
  /// A device fixed in the world at X_WD: X_W_robot_from_base(BasePose{}) is the identity.
  [[nodiscard]] static Rig desktop(const Pose& X_WD, const PhantomModel& device = phantom_premium_1_5());

  [[nodiscard]] RigKind kind() const noexcept { return kind_; }

  // Fixed transforms (from the file).
  [[nodiscard]] const Pose& X_W_is900() const noexcept { return X_W_is900_; }
  [[nodiscard]] const Pose& X_is900_base_sensor_nominal() const noexcept { return X_is900_base_sensor_nominal_; }
  [[nodiscard]] const Pose& X_base_sensor_robot() const noexcept { return X_base_sensor_robot_; }
  [[nodiscard]] const Pose& X_robot_phantom() const noexcept { return X_robot_phantom_; }
  [[nodiscard]] const Pose& X_robot_base() const noexcept { return X_robot_base_; }
  [[nodiscard]] const PhantomModel& device() const noexcept { return device_; }
  /// The lift, if the rig has one.
  [[nodiscard]] const std::optional<Lift>& lift() const noexcept { return lift_; }
  /// The arm's frame P in the robot frame with the lift at `lift_m` (0: the file's frame).
  [[nodiscard]] Pose X_robot_phantom(double lift_m) const noexcept;

  // Where the robot is: from a tracker measurement, or from a planar base pose.
  [[nodiscard]] Pose X_W_robot_from_sensor(const Pose& X_is900_base_sensor) const noexcept;
  [[nodiscard]] Pose X_W_robot_from_base(const BasePose& base) const noexcept;
  /// The planar base pose a tracker measurement means (for the base pose predictor).
  [[nodiscard]] BasePose base_from_sensor(const Pose& X_is900_base_sensor) const noexcept;
  /// The tracker measurement a planar base pose gives (for a simulated tracker).
  [[nodiscard]] Pose X_is900_base_sensor_from_base(const BasePose& base) const noexcept;

  // From the robot's pose and the joint angles to the tool.
  [[nodiscard]] Pose X_W_phantom(const Pose& X_W_robot, double lift_m = 0.0) const noexcept;
  [[nodiscard]] Pose X_W_tool(const Pose& X_W_robot, const Eigen::Vector3d& q_rad, double lift_m = 0.0) const noexcept;
  [[nodiscard]] Eigen::Vector3d p_W_hip(const Pose& X_W_robot, const Eigen::Vector3d& q_rad,
                                        double lift_m = 0.0) const noexcept;
  /// A point the device reports in its frame P (a Cartesian device's tool, ABI 3) in the world.
  [[nodiscard]] Eigen::Vector3d p_W_from_device(const Pose& X_W_robot, const Eigen::Vector3d& p_P_m,
                                                double lift_m = 0.0) const noexcept;
  /// A force given in the world, in the device frame P (what a Cartesian device receives).
  /// Thesis ch. 5.2: with the base position-controlled and much heavier than the arm, the
  /// base's motion does not enter the force command.
  [[nodiscard]] Eigen::Vector3d force_P_from_W(const Pose& X_W_robot, const Eigen::Vector3d& force_W_N) const noexcept;
  /// A world point in the device frame P (e.g. the user's hand, for the simulated device's IK).
  [[nodiscard]] Eigen::Vector3d p_P_from_W(const Pose& X_W_robot, const Eigen::Vector3d& p_W,
                                           double lift_m = 0.0) const noexcept;

  /// Joint torques for a force on the tool given in the world: tau = J_P^T (R_W_P^T F_W).
  /// Thesis ch. 5.2: with the base position-controlled and much heavier than the arm, the
  /// base's part of the Jacobian drops out of the torque command.
  [[nodiscard]] Eigen::Vector3d joint_torques_Nm(const Pose& X_W_robot, const Eigen::Vector3d& q_rad,
                                                 const Eigen::Vector3d& force_W_N) const noexcept;

  /// d p_W_hip / d (base x, base y, base z, heading, theta1, theta2, theta3) at a planar base
  /// pose (base y: a vertical offset of the whole base, 0 here). Thesis eq. 5.1; its phi is
  /// the tracker's yaw, phi = pi - heading with pomhi.xml, so d/dphi = -d/dheading.
  [[nodiscard]] HipJacobian hip_jacobian(const BasePose& base, const Eigen::Vector3d& q_rad) const noexcept;

 private:
  Rig() = default;
  /// This rig with `lift` (from_scene), or why it cannot carry it.
  [[nodiscard]] Result<Rig, std::vector<RigError>> with_lift(const LiftDescription& lift) &&;

  RigKind kind_ = RigKind::Mobile;
  PhantomModel device_;
  Pose X_W_is900_ = Pose::Identity();
  Pose X_is900_base_sensor_nominal_ = Pose::Identity();
  Pose X_base_sensor_robot_ = Pose::Identity();
  Pose X_robot_phantom_ = Pose::Identity();
  Pose X_robot_base_ = Pose::Identity();
  Pose X_base_robot_ = Pose::Identity();  ///< inverse of X_robot_base_
  std::optional<Lift> lift_;
};

}  // namespace mhd
