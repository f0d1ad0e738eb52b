#include "plugin_host/abi_conversion.h"

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace mhd {
namespace {

static_assert(DeviceInfo::kMaxWorkspaceBoxes == MHD_DEVICE_MAX_WORKSPACE_BOXES);

template <class A, class Abi>
concept Is = std::same_as<std::remove_const_t<A>, Abi>;

// Each struct's fields are listed once, as pairs f(abi field, engine field), and serve
// both directions.
template <class A, class C, class F>
  requires Is<A, mhd_device_state>
void fields(A& a, C& c, F&& f) {
  f(a.timestamp_s, c.timestamp_s);
  f(a.p_D_tool_m, c.p_D_tool_m);
  f(a.v_D_tool_mps, c.v_D_tool_mps);
  f(a.q_D_tool_wxyz, c.q_D_tool_wxyz);
  f(a.buttons, c.buttons);
}

template <class A, class C, class F>
  requires Is<A, mhd_device_command>
void fields(A& a, C& c, F&& f) {
  f(a.timestamp_s, c.timestamp_s);
  f(a.force_D_N, c.force_D_N);
  f(a.torque_D_Nm, c.torque_D_Nm);
}

template <class A, class C, class F>
  requires Is<A, mhd_device_info>
void fields(A& a, C& c, F&& f) {
  f(a.max_force_N, c.max_force_N);
  f(a.max_torque_Nm, c.max_torque_Nm);
  f(a.max_stiffness_N_per_m, c.max_stiffness_N_per_m);
  f(a.dof_in, c.dof_in);
  f(a.dof_out, c.dof_out);
  f(a.workspace_box_count, c.workspace_box_count);  // as reported: a check judges it
  for (std::size_t b = 0; b < DeviceInfo::kMaxWorkspaceBoxes; ++b) {
    f(a.workspace[b].min_m, c.workspace[b].min_m);
    f(a.workspace[b].max_m, c.workspace[b].max_m);
  }
}

template <class A, class C, class F>
  requires Is<A, mhd_tracker_sample>
void fields(A& a, C& c, F&& f) {
  f(a.sensor_id, c.sensor_id);
  f(a.sequence, c.sequence);
  f(a.timestamp_s, c.timestamp_s);
  f(a.p_T_m, c.p_T_m);
  f(a.q_T_wxyz, c.q_T_wxyz);
}

template <class A, class C, class F>
  requires Is<A, mhd_base_state>
void fields(A& a, C& c, F&& f) {
  f(a.timestamp_s, c.timestamp_s);
  f(a.x_m, c.x_m);
  f(a.z_m, c.z_m);
  f(a.heading_rad, c.heading_rad);
  f(a.vx_mps, c.vx_mps);
  f(a.vz_mps, c.vz_mps);
  f(a.omega_radps, c.omega_radps);
  f(a.has_lift, c.has_lift);
  f(a.lift_m, c.lift_m);
  f(a.lift_vmps, c.lift_vmps);
}

template <class A, class C, class F>
  requires Is<A, mhd_base_command>
void fields(A& a, C& c, F&& f) {
  f(a.timestamp_s, c.timestamp_s);
  f(a.vx_mps, c.vx_mps);
  f(a.vz_mps, c.vz_mps);
  f(a.omega_radps, c.omega_radps);
  f(a.lift_vmps, c.lift_vmps);
}

template <class A, class C, class F>
  requires Is<A, mhd_display_frame>
void fields(A& a, C& c, F&& f) {
  f(a.timestamp_s, c.timestamp_s);
  f(a.p_W_hip_m, c.p_W_hip_m);
  f(a.p_W_proxy_m, c.p_W_proxy_m);
  f(a.force_W_N, c.force_W_N);
  f(a.in_contact, c.in_contact);
  f(a.base_x_m, c.base_x_m);
  f(a.base_z_m, c.base_z_m);
  f(a.base_heading_rad, c.base_heading_rad);
  f(a.p_W_head_m, c.p_W_head_m);
  f(a.q_W_head_wxyz, c.q_W_head_wxyz);
}

template <class A, class C, class F>
  requires Is<A, mhd_link_message>
void fields(A& a, C& c, F&& f) {
  f(a.kind, c.kind);
  f(a.object_id, c.object_id);
  f(a.rig_id, c.rig_id);
  f(a.term, c.term);
  f(a.sequence, c.sequence);
  f(a.timestamp_s, c.timestamp_s);
  f(a.p_W_m, c.p_W_m);
  f(a.q_W_wxyz, c.q_W_wxyz);
  f(a.v_W_mps, c.v_W_mps);
  f(a.w_W_radps, c.w_W_radps);
  f(a.f_W_N, c.f_W_N);
  f(a.p_O_m, c.p_O_m);
}

template <class A, class C, class F>
  requires Is<A, mhd_counter>
void fields(A& a, C& c, F&& f) {
  f(a.name, c.name);
  f(a.value, c.value);
}

// One field, either way: numbers and names as they are, arrays element by element, and
// the ABI's int32 flag as the engine's bool, the ABI's uint32 kind as the engine's enum
// (any number: a check judges it).
template <class To, class From>
void assign(To& to, const From& from) {
  if constexpr (std::is_array_v<To> || std::is_array_v<From>) {
    for (std::size_t i = 0; i < std::size(to); ++i) to[i] = from[i];
  } else if constexpr (std::same_as<To, bool>) {
    to = from != 0;
  } else if constexpr (std::same_as<From, bool>) {
    to = from ? 1 : 0;
  } else if constexpr (std::is_enum_v<To> || std::is_enum_v<From>) {
    to = static_cast<To>(from);
  } else {
    to = from;
  }
}

template <class Engine, class Abi>
Engine engine_from(const Abi& a) {
  Engine c{};
  fields(a, c, [](const auto& from, auto& to) { assign(to, from); });
  return c;
}

template <class Abi, class Engine>
Abi abi_from(const Engine& c) {
  // Zeroed whole, padding too: no byte of this process's stack reaches a plugin.
  Abi a;
  std::memset(&a, 0, sizeof a);
  fields(a, c, [](auto& to, const auto& from) { assign(to, from); });
  return a;
}

}  // namespace

DeviceState from_abi(const mhd_device_state& s) noexcept { return engine_from<DeviceState>(s); }
mhd_device_state to_abi(const DeviceState& s) noexcept { return abi_from<mhd_device_state>(s); }
DeviceCommand from_abi(const mhd_device_command& c) noexcept { return engine_from<DeviceCommand>(c); }
mhd_device_command to_abi(const DeviceCommand& c) noexcept { return abi_from<mhd_device_command>(c); }
DeviceInfo from_abi(const mhd_device_info& info) noexcept { return engine_from<DeviceInfo>(info); }
mhd_device_info to_abi(const DeviceInfo& info) noexcept { return abi_from<mhd_device_info>(info); }
TrackerSample from_abi(const mhd_tracker_sample& s) noexcept { return engine_from<TrackerSample>(s); }
mhd_tracker_sample to_abi(const TrackerSample& s) noexcept { return abi_from<mhd_tracker_sample>(s); }
BaseState from_abi(const mhd_base_state& s) noexcept { return engine_from<BaseState>(s); }
mhd_base_state to_abi(const BaseState& s) noexcept { return abi_from<mhd_base_state>(s); }
BaseCommand from_abi(const mhd_base_command& c) noexcept { return engine_from<BaseCommand>(c); }
mhd_base_command to_abi(const BaseCommand& c) noexcept { return abi_from<mhd_base_command>(c); }
DisplayFrame from_abi(const mhd_display_frame& f) noexcept { return engine_from<DisplayFrame>(f); }
mhd_display_frame to_abi(const DisplayFrame& f) noexcept { return abi_from<mhd_display_frame>(f); }
LinkMessage from_abi(const mhd_link_message& m) noexcept { return engine_from<LinkMessage>(m); }
mhd_link_message to_abi(const LinkMessage& m) noexcept { return abi_from<mhd_link_message>(m); }
CounterReading from_abi(const mhd_counter& c) noexcept { return engine_from<CounterReading>(c); }

}  // namespace mhd
