#pragma once
// What the test device plugins (tests/haptic_server/plugins, tests/fault_injection/plugins)
// report as a device: a PHANToM Premium 1.5's limits and workspace box in its frame, and
// a tool point near the middle of that workspace. Header-only, plugin side.

#include <mhd/plugin_abi.h>

#include <array>

namespace test_plugins {

/// A PHANToM's tool at joint angles (0, 0.3, 0.2) rad, device frame, m.
inline constexpr std::array<double, 3> kPhantomMidTool_D_m{0.0, 0.06610330791925151, 0.032271919564375806};

/// A PHANToM Premium 1.5's peak force, the limit the test devices report (N).
inline constexpr double kPhantomMaxForce_N = 8.5;

/// A 3-in, 3-out device with a PHANToM Premium 1.5's force, stiffness and workspace box.
inline mhd_device_info phantom_like_device_info() {
  mhd_device_info out{};
  out.max_force_N = kPhantomMaxForce_N;
  out.max_stiffness_N_per_m = 3500.0;
  out.dof_in = 3;
  out.dof_out = 3;
  out.workspace_box_count = 1;
  constexpr std::array<double, 3> min_D_m{-0.1905, -0.0035, -0.1055}, max_D_m{0.1905, 0.2635, 0.0855};
  for (int i = 0; i < 3; ++i) {
    out.workspace[0].min_m[i] = min_D_m[static_cast<std::size_t>(i)];
    out.workspace[0].max_m[i] = max_D_m[static_cast<std::size_t>(i)];
  }
  return out;
}

}  // namespace test_plugins
