#include "kinematics/rig.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace mhd {

namespace {

constexpr double kLevelTolerance_rad = 1e-4;
constexpr double kFloorTolerance_m = 1e-4;

struct RequiredFrame {
  std::string_view name;
  std::string_view parent;
};

// The chain in the order it is composed.
constexpr std::array<RequiredFrame, 5> kRequired = {{
    {rig_frame::kIs900, "world"},
    {rig_frame::kBaseSensor, rig_frame::kIs900},
    {rig_frame::kRobot, rig_frame::kBaseSensor},
    {rig_frame::kPhantom, rig_frame::kRobot},
    {rig_frame::kBase, rig_frame::kRobot},
}};

// Appending piece by piece (std::string's operator+ chains trip GCC 12's -Wrestrict).
template <typename... Parts>
std::string concat(const Parts&... parts) {
  std::string out;
  (out.append(std::string_view(parts)), ...);
  return out;
}

std::string in_quotes(std::string_view s) { return concat("'", s, "'"); }

std::string format_degrees(double value_rad) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.4g", value_rad * 180.0 / std::numbers::pi);
  return std::string(buffer.data());
}

std::string format_metres(double value_m) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.6g", value_m);
  return std::string(buffer.data());
}

}  // namespace

std::string RigError::to_string() const {
  if (where.file.empty()) return concat("error: ", message);
  if (where.line <= 0) return concat(where.file, ": error: ", message);
  return concat(where.file, ":", std::to_string(where.line), ": error: ", message);
}

Result<Rig, std::vector<RigError>> Rig::from_scene(const SceneDescription& scene, const PhantomModel& device) {
  if (scene.rig_kind.kind == RigKind::Mobile) {
    auto rig = from_frames(scene.rig_frames, device);
    if (!rig || !scene.rig_lift) return rig;
    return std::move(rig).value().with_lift(*scene.rig_lift);
  }
  if (scene.rig_lift) {
    return std::vector<RigError>{{RigErrorKind::LiftOnDesktop, "lift",
                                  "a desktop rig has no base to carry a <lift>: use a mobile rig",
                                  scene.rig_lift->where}};
  }
  for (const FrameDescription& frame : scene.rig_frames) {
    if (frame.name == "device" && frame.parent == "world") return desktop(frame.X_PF, device);
  }
  // The scene reader refuses such a scene already; a description built in code may not.
  return std::vector<RigError>{{RigErrorKind::MissingFrame, "device",
                                "desktop rig has no frame 'device' (expected <frame name=\"device\" parent=\"world\" .../>)",
                                scene.rig_kind.where.value_or(SourceLocation{})}};
}

Rig Rig::desktop(const Pose& X_WD, const PhantomModel& device) {
  Rig rig;
  rig.kind_ = RigKind::Desktop;
  rig.device_ = device;
  // Base, robot and tracker frames all coincide with the world; only D is placed.
  rig.X_robot_phantom_ = X_WD;
  return rig;
}

Result<Rig, std::vector<RigError>> Rig::from_frames(const std::vector<FrameDescription>& frames, const PhantomModel& device) {
  std::vector<RigError> errors;
  std::array<const FrameDescription*, kRequired.size()> found{};
  for (std::size_t i = 0; i < kRequired.size(); ++i) {
    const RequiredFrame& required = kRequired[i];
    for (const FrameDescription& frame : frames) {
      if (frame.name != required.name) continue;
      if (found[i] != nullptr) {
        errors.push_back({RigErrorKind::DuplicateFrame, frame.name,
                                 concat("rig frame ", in_quotes(frame.name), " is defined twice (first at ",
                                        found[i]->where.file, ":", std::to_string(found[i]->where.line), ")"),
                                 frame.where});
        continue;
      }
      found[i] = &frame;
    }
    if (found[i] == nullptr) {
      errors.push_back({RigErrorKind::MissingFrame, std::string(required.name),
                               concat("rig has no frame ", in_quotes(required.name), " (expected <frame name=\"",
                                      required.name, "\" parent=\"", required.parent, "\" .../>)"),
                               SourceLocation{}});
    } else if (found[i]->parent != required.parent) {
      errors.push_back({RigErrorKind::WrongParent, found[i]->name,
                               concat("rig frame ", in_quotes(found[i]->name), " must have parent ",
                                      in_quotes(required.parent), ", not ", in_quotes(found[i]->parent)),
                               found[i]->where});
    }
  }
  if (!errors.empty()) return errors;

  Rig rig;
  rig.device_ = device;
  rig.X_W_is900_ = found[0]->X_PF;
  rig.X_is900_base_sensor_nominal_ = found[1]->X_PF;
  rig.X_base_sensor_robot_ = found[2]->X_PF;
  rig.X_robot_phantom_ = found[3]->X_PF;
  rig.X_robot_base_ = found[4]->X_PF;
  rig.X_base_robot_ = rig.X_robot_base_.inverse(Eigen::Isometry);

  const Pose X_W_base = rig.X_W_robot_from_sensor(rig.X_is900_base_sensor_nominal_) * rig.X_robot_base_;
  const double tilt_rad = std::acos(std::clamp(X_W_base.linear().col(1).dot(Eigen::Vector3d::UnitY()), -1.0, 1.0));
  const FrameDescription& base = *found[4];
  if (tilt_rad > kLevelTolerance_rad) {
    errors.push_back({RigErrorKind::BaseNotLevel, base.name,
                             concat("rig frame 'base' is not level: with base_sensor at its nominal pose, its y "
                                    "axis is ",
                                    format_degrees(tilt_rad), " degrees from world up"),
                             base.where});
  }
  const double height_m = X_W_base.translation().y();
  if (std::abs(height_m) > kFloorTolerance_m) {
    errors.push_back({RigErrorKind::BaseNotOnFloor, base.name,
                             concat("rig frame 'base' is not on the floor: with base_sensor at its nominal pose, "
                                    "it is at y = ",
                                    format_metres(height_m), " m"),
                             base.where});
  }
  if (!errors.empty()) return errors;
  return rig;
}

Pose Rig::X_W_robot_from_sensor(const Pose& X_is900_base_sensor) const noexcept {
  return X_W_is900_ * X_is900_base_sensor * X_base_sensor_robot_;
}

Pose Rig::X_W_robot_from_base(const BasePose& base) const noexcept { return pose_from_base(base) * X_base_robot_; }

BasePose Rig::base_from_sensor(const Pose& X_is900_base_sensor) const noexcept {
  return base_from_pose(X_W_robot_from_sensor(X_is900_base_sensor) * X_robot_base_);
}

Result<Rig, std::vector<RigError>> Rig::with_lift(const LiftDescription& lift) && {
  // The lift moves the arm along the robot's z: it must be world up, as the base's y is.
  const Eigen::Vector3d z_W = (X_W_robot_from_sensor(X_is900_base_sensor_nominal_).linear() * Eigen::Vector3d::UnitZ());
  const double tilt_rad = std::acos(std::clamp(z_W.dot(Eigen::Vector3d::UnitY()), -1.0, 1.0));
  if (tilt_rad > kLevelTolerance_rad) {
    return std::vector<RigError>{{RigErrorKind::LiftNotVertical, "lift",
                                  concat("the lift moves the arm along the robot frame's z, which is ",
                                         format_degrees(tilt_rad),
                                         " degrees from world up with base_sensor at its nominal pose: turn the "
                                         "'robot' frame so that its z is up"),
                                  lift.where}};
  }
  lift_ = Lift{lift.min_m, lift.max_m, lift.max_speed_mps, lift.max_acceleration_mps2};
  return std::move(*this);
}

Pose Rig::X_is900_base_sensor_from_base(const BasePose& base) const noexcept {
  return X_W_is900_.inverse(Eigen::Isometry) * X_W_robot_from_base(base) *
         X_base_sensor_robot_.inverse(Eigen::Isometry);
}

Pose Rig::X_robot_phantom(double lift_m) const noexcept {
  Pose X = X_robot_phantom_;
  X.translation().z() += lift_m;
  return X;
}

Pose Rig::X_W_phantom(const Pose& X_W_robot, double lift_m) const noexcept {
  return X_W_robot * X_robot_phantom(lift_m);
}

Pose Rig::X_W_tool(const Pose& X_W_robot, const Eigen::Vector3d& q_rad, double lift_m) const noexcept {
  return X_W_phantom(X_W_robot, lift_m) * phantom_tool_pose(device_.geometry, q_rad);
}

Eigen::Vector3d Rig::p_W_hip(const Pose& X_W_robot, const Eigen::Vector3d& q_rad, double lift_m) const noexcept {
  return X_W_phantom(X_W_robot, lift_m) * phantom_tool_position(device_.geometry, q_rad);
}

Eigen::Vector3d Rig::p_W_from_device(const Pose& X_W_robot, const Eigen::Vector3d& p_P_m,
                                     double lift_m) const noexcept {
  return X_W_phantom(X_W_robot, lift_m) * p_P_m;
}

Eigen::Vector3d Rig::force_P_from_W(const Pose& X_W_robot, const Eigen::Vector3d& force_W_N) const noexcept {
  return X_W_phantom(X_W_robot).linear().transpose() * force_W_N;
}

Eigen::Vector3d Rig::p_P_from_W(const Pose& X_W_robot, const Eigen::Vector3d& p_W, double lift_m) const noexcept {
  return X_W_phantom(X_W_robot, lift_m).inverse(Eigen::Isometry) * p_W;
}

Eigen::Vector3d Rig::joint_torques_Nm(const Pose& X_W_robot, const Eigen::Vector3d& q_rad,
                                      const Eigen::Vector3d& force_W_N) const noexcept {
  const Eigen::Matrix3d R_W_P = X_W_phantom(X_W_robot).linear();
  return phantom_joint_torques(device_.geometry, q_rad, R_W_P.transpose() * force_W_N);
}

Rig::HipJacobian Rig::hip_jacobian(const BasePose& base, const Eigen::Vector3d& q_rad) const noexcept {
  const Pose X_W_robot = X_W_robot_from_base(base);
  const Pose X_W_P = X_W_phantom(X_W_robot);
  const Eigen::Vector3d p_W = X_W_P * phantom_tool_position(device_.geometry, q_rad);
  HipJacobian J;
  J.leftCols<3>().setIdentity();
  // Turning the base about the vertical through its origin moves the HIP by up x (p - base).
  const Eigen::Vector3d lever_W = p_W - Eigen::Vector3d(base.x_m, 0.0, base.z_m);
  J.col(kBaseHeading) = Eigen::Vector3d::UnitY().cross(lever_W);
  J.rightCols<3>() = X_W_P.linear() * phantom_position_jacobian(device_.geometry, q_rad);
  return J;
}

}  // namespace mhd
