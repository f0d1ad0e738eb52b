// The engine's hardware_io.h structs and the ABI's: every field crosses both ways
// unchanged (each given a value of its own, so a swapped or missed field shows), and the
// ABI's int32 contact flag is the engine's bool.
#include "plugin_host/abi_conversion.h"

#include <gtest/gtest.h>

#include <cstring>

namespace {

using namespace mhd;

/// A struct of the ABI with every byte zero, padding too, so that memcmp compares fields.
template <class T>
T zeroed() {
  T t;
  std::memset(&t, 0, sizeof t);
  return t;
}

/// Whether `a`, converted to the engine's struct and back, is byte for byte `a`.
template <class Abi>
bool survives_the_round_trip(const Abi& a) {
  const Abi back = to_abi(from_abi(a));
  return std::memcmp(&back, &a, sizeof a) == 0;
}

/// 1.0, 2.0, ... into every double of `values`.
template <std::size_t N>
void number(double (&values)[N], double& next) {
  for (double& v : values) v = (next += 1.0);
}

TEST(AbiConversion, ADeviceStateCrossesBothWaysFieldByField) {
  double next = 0.0;
  auto a = zeroed<mhd_device_state>();
  a.timestamp_s = (next += 1.0);
  number(a.p_D_tool_m, next);
  number(a.v_D_tool_mps, next);
  number(a.q_D_tool_wxyz, next);
  a.buttons = 0x5u;
  const DeviceState c = from_abi(a);
  EXPECT_EQ(c.timestamp_s, 1.0);
  EXPECT_EQ(c.p_D_tool_m[2], 4.0);
  EXPECT_EQ(c.v_D_tool_mps[0], 5.0);
  EXPECT_EQ(c.q_D_tool_wxyz[3], 11.0);
  EXPECT_EQ(c.buttons, 0x5u);
  EXPECT_TRUE(survives_the_round_trip(a));
}

TEST(AbiConversion, DeviceInfoKeepsEveryBoxAndTheCountAsReported) {
  auto a = zeroed<mhd_device_info>();
  a.max_force_N = 3.3;
  a.max_torque_Nm = 0.2;
  a.max_stiffness_N_per_m = 1260.0;
  a.dof_in = 6;
  a.dof_out = 3;
  a.workspace_box_count = 99;  // out of range: kept, so the host's check can refuse it
  double next = 0.0;
  for (mhd_box_D& box : a.workspace) {
    number(box.min_m, next);
    number(box.max_m, next);
  }
  const DeviceInfo c = from_abi(a);
  EXPECT_EQ(c.workspace_box_count, 99u);
  EXPECT_EQ(c.dof_in, 6u);
  EXPECT_EQ(c.dof_out, 3u);
  EXPECT_EQ(c.workspace[3].max_m[2], 24.0);
  EXPECT_TRUE(survives_the_round_trip(a));
}

TEST(AbiConversion, CommandsSamplesAndBaseStatesCrossBothWays) {
  double next = 0.0;
  auto command = zeroed<mhd_device_command>();
  command.timestamp_s = 0.5;
  number(command.force_D_N, next);
  number(command.torque_D_Nm, next);
  EXPECT_TRUE(survives_the_round_trip(command));
  EXPECT_EQ(from_abi(command).torque_D_Nm[2], 6.0);

  auto sample = zeroed<mhd_tracker_sample>();
  sample.sensor_id = 7;
  sample.sequence = 1ull << 40;
  sample.timestamp_s = 2.5;
  number(sample.p_T_m, next);
  number(sample.q_T_wxyz, next);
  EXPECT_EQ(from_abi(sample).sequence, 1ull << 40);
  EXPECT_EQ(from_abi(sample).q_T_wxyz[0], 10.0);
  EXPECT_TRUE(survives_the_round_trip(sample));

  // Zeroed whole, padding too, as to_abi makes them: the round trip compares bytes.
  auto state = zeroed<mhd_base_state>();
  next = 0.0;
  for (double* field : {&state.timestamp_s, &state.x_m, &state.z_m, &state.heading_rad, &state.vx_mps, &state.vz_mps,
                        &state.omega_radps}) {
    *field = (next += 1.0);
  }
  state.has_lift = 1;
  state.lift_m = 8.0;
  state.lift_vmps = 9.0;
  EXPECT_EQ(from_abi(state).heading_rad, 4.0);
  EXPECT_EQ(from_abi(state).omega_radps, 7.0);
  EXPECT_TRUE(from_abi(state).has_lift);
  EXPECT_EQ(from_abi(state).lift_m, 8.0);
  EXPECT_EQ(from_abi(state).lift_vmps, 9.0);
  EXPECT_TRUE(survives_the_round_trip(state));
  // A base that leaves the lift fields as the host zeroed them has none.
  auto no_lift = zeroed<mhd_base_state>();
  no_lift.timestamp_s = 1.0;
  no_lift.x_m = 2.0;
  EXPECT_FALSE(from_abi(no_lift).has_lift);
  EXPECT_TRUE(survives_the_round_trip(no_lift));

  const mhd_base_command twist{1.0, 0.25, -0.5, 0.75, -0.125};
  EXPECT_EQ(from_abi(twist).vz_mps, -0.5);
  EXPECT_EQ(from_abi(twist).lift_vmps, -0.125);
  EXPECT_TRUE(survives_the_round_trip(twist));
}

TEST(AbiConversion, ADisplayFrameCrossesAndItsContactFlagIsABool) {
  double next = 0.0;
  auto a = zeroed<mhd_display_frame>();
  a.timestamp_s = 0.25;
  number(a.p_W_hip_m, next);
  number(a.p_W_proxy_m, next);
  number(a.force_W_N, next);
  a.in_contact = 7;  // any non-zero int32 is contact
  a.base_x_m = 10.5;
  a.base_z_m = 11.5;
  a.base_heading_rad = 0.3;
  number(a.p_W_head_m, next);
  number(a.q_W_head_wxyz, next);
  const DisplayFrame c = from_abi(a);
  EXPECT_TRUE(c.in_contact);
  EXPECT_EQ(c.force_W_N[0], 7.0);
  EXPECT_EQ(c.q_W_head_wxyz[3], 16.0);
  EXPECT_EQ(c.base_z_m, 11.5);
  EXPECT_EQ(to_abi(c).in_contact, 1);
  a.in_contact = 1;
  EXPECT_TRUE(survives_the_round_trip(a));
  a.in_contact = 0;
  EXPECT_FALSE(from_abi(a).in_contact);
  EXPECT_EQ(to_abi(from_abi(a)).in_contact, 0);
}

TEST(AbiConversion, ACounterKeepsThePluginsNameAndValue) {
  static const char kName[] = "dropped_stale";
  const CounterReading c = from_abi(mhd_counter{kName, 12});
  EXPECT_EQ(c.name, kName);
  EXPECT_EQ(c.value, 12u);
}

}  // namespace
