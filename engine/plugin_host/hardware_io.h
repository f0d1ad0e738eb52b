#pragma once
// What the host and its plugins exchange, as the engine sees it: the C++ twins of the
// plugin ABI's data structs (mhd/plugin_abi.h). Fields keep the ABI's names, frames and
// units. The engine speaks only these; plugin_host converts them to and from the ABI
// (abi_conversion.h) at every call, and no other engine layer sees the ABI header.

#include <array>
#include <cstddef>
#include <cstdint>

namespace mhd {

/// The tool in the device's own frame D, on the host clock. A device with 3 input DOF
/// reports q_D_tool_wxyz = (1, 0, 0, 0).
struct DeviceState {
  double timestamp_s = 0.0;
  std::array<double, 3> p_D_tool_m{};
  std::array<double, 3> v_D_tool_mps{};
  std::array<double, 4> q_D_tool_wxyz{1.0, 0.0, 0.0, 0.0};  ///< unit quaternion w, x, y, z
  std::uint32_t buttons = 0;                                ///< bit i: button i pressed
};

/// The force (and torque) to render at the tool, in D.
struct DeviceCommand {
  double timestamp_s = 0.0;
  std::array<double, 3> force_D_N{};
  std::array<double, 3> torque_D_Nm{};
};

/// An axis-aligned box in the device frame D.
struct WorkspaceBoxD {
  std::array<double, 3> min_m{};
  std::array<double, 3> max_m{};
};

/// What a device is, as it reported after open().
struct DeviceInfo {
  static constexpr std::size_t kMaxWorkspaceBoxes = 4;
  double max_force_N = 0.0;
  double max_torque_Nm = 0.0;  ///< > 0 with 6 output DOF, 0 with 3
  double max_stiffness_N_per_m = 0.0;
  std::uint32_t dof_in = 0;   ///< 3 (position) or 6 (position and orientation)
  std::uint32_t dof_out = 0;  ///< 3 (force) or 6 (force and torque)
  std::uint32_t workspace_box_count = 0;
  std::array<WorkspaceBoxD, kMaxWorkspaceBoxes> workspace{};  ///< their union is what the tool reaches
};

/// One pose sample of one sensor in the tracker's frame T (X_T_sensor).
struct TrackerSample {
  std::uint32_t sensor_id = 0;
  std::uint64_t sequence = 0;  ///< per sensor, increasing
  double timestamp_s = 0.0;    ///< when the pose was measured, host clock
  std::array<double, 3> p_T_m{};
  std::array<double, 4> q_T_wxyz{1.0, 0.0, 0.0, 0.0};
};

/// The base's planar pose on the floor (world x, z; heading about world +y) and velocity.
struct BaseState {
  double timestamp_s = 0.0;
  double x_m = 0.0, z_m = 0.0, heading_rad = 0.0;
  double vx_mps = 0.0, vz_mps = 0.0, omega_radps = 0.0;  ///< in the world frame
  bool has_lift = false;   ///< the base carries a lift, whose state the next two are
  double lift_m = 0.0;     ///< the arm's height above the rig file's (Rig::X_robot_phantom)
  double lift_vmps = 0.0;  ///< up positive
};

/// The base's velocity in its own frame (x forward, y up, z to the right).
struct BaseCommand {
  double timestamp_s = 0.0;
  double vx_mps = 0.0, vz_mps = 0.0, omega_radps = 0.0;
  double lift_vmps = 0.0;  ///< the lift's vertical speed, up positive (0: hold)
};

/// What rigs sharing an object tell each other: the authority's state of the object, or
/// a rig's push on it (docs/shared-objects.md).
enum class LinkMessageKind : std::uint32_t { State = 1, Push = 2 };

struct LinkMessage {
  LinkMessageKind kind = LinkMessageKind::State;
  std::uint32_t object_id = 0;  ///< as the scenes' <shared_object id> give it
  std::uint32_t rig_id = 0;     ///< the sender
  std::uint32_t term = 0;       ///< state: the authority's term
  std::uint64_t sequence = 0;   ///< per sender and kind, increasing
  double timestamp_s = 0.0;     ///< host clock
  std::array<double, 3> p_W_m{};                       ///< state: the object's origin
  std::array<double, 4> q_W_wxyz{1.0, 0.0, 0.0, 0.0};  ///< state: its orientation
  std::array<double, 3> v_W_mps{};                     ///< state: its origin's velocity
  std::array<double, 3> w_W_radps{};                   ///< state: its angular velocity
  std::array<double, 3> f_W_N{};                       ///< push: the force
  std::array<double, 3> p_O_m{};                       ///< push: where, in the object's frame
};

/// A snapshot of the rig for drawing, in the world frame.
struct DisplayFrame {
  double timestamp_s = 0.0;
  std::array<double, 3> p_W_hip_m{};
  std::array<double, 3> p_W_proxy_m{};
  std::array<double, 3> force_W_N{};
  bool in_contact = false;
  double base_x_m = 0.0, base_z_m = 0.0, base_heading_rad = 0.0;
  std::array<double, 3> p_W_head_m{};
  std::array<double, 4> q_W_head_wxyz{1.0, 0.0, 0.0, 0.0};
};

/// One of a plugin's counters. The name is the plugin's static string, valid while its
/// library is loaded.
struct CounterReading {
  const char* name = nullptr;
  std::uint64_t value = 0;
};

}  // namespace mhd
