#include "plugin_host/device_info_check.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace mhd {
namespace {

std::optional<std::string> first_non_finite(const char* name, const double* values, int count) {
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) return count == 1 ? fmt::format("{}", name) : fmt::format("{}[{}]", name, i);
  }
  return std::nullopt;
}

double norm3(const std::array<double, 3>& v) noexcept { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

void scale_to(std::array<double, 3>& v, double limit) noexcept {
  const double n = norm3(v);
  if (n <= limit || n == 0.0) return;
  const double k = limit / n;
  for (int i = 0; i < 3; ++i) v[i] *= k;
}

}  // namespace

std::optional<std::string> device_info_problem(const DeviceInfo& info) {
  for (const auto& [name, value] : {std::pair{"max_force_N", info.max_force_N}, std::pair{"max_torque_Nm", info.max_torque_Nm},
                                    std::pair{"max_stiffness_N_per_m", info.max_stiffness_N_per_m}}) {
    if (!std::isfinite(value)) return fmt::format("{} is not finite", name);
  }
  if (!(info.max_force_N > 0.0)) return fmt::format("max_force_N = {}, which must be > 0", info.max_force_N);
  if (!(info.max_stiffness_N_per_m > 0.0)) {
    return fmt::format("max_stiffness_N_per_m = {}, which must be > 0", info.max_stiffness_N_per_m);
  }
  if (info.dof_in != 3 && info.dof_in != 6) return fmt::format("dof_in = {}, which must be 3 or 6", info.dof_in);
  if (info.dof_out != 3 && info.dof_out != 6) return fmt::format("dof_out = {}, which must be 3 or 6", info.dof_out);
  if (info.dof_out == 6 && !(info.max_torque_Nm > 0.0)) {
    return fmt::format("max_torque_Nm = {}, which must be > 0 with dof_out 6", info.max_torque_Nm);
  }
  if (info.dof_out == 3 && info.max_torque_Nm != 0.0) {
    return fmt::format("max_torque_Nm = {}, which must be 0 with dof_out 3", info.max_torque_Nm);
  }
  if (info.workspace_box_count < 1 || info.workspace_box_count > DeviceInfo::kMaxWorkspaceBoxes) {
    return fmt::format("workspace_box_count = {}, which must be 1 to {}", info.workspace_box_count,
                       DeviceInfo::kMaxWorkspaceBoxes);
  }
  for (std::uint32_t b = 0; b < info.workspace_box_count; ++b) {
    const WorkspaceBoxD& box = info.workspace[b];
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(box.min_m[i]) || !std::isfinite(box.max_m[i]) || !(box.min_m[i] < box.max_m[i])) {
        return fmt::format("workspace[{}] has min_m[{}] = {} and max_m[{}] = {}; they must be finite with min < max", b,
                           i, box.min_m[i], i, box.max_m[i]);
      }
    }
  }
  return std::nullopt;
}

std::optional<std::string> device_state_problem(const DeviceState& s) {
  if (!std::isfinite(s.timestamp_s)) return std::string("a non-finite timestamp_s");
  if (auto f = first_non_finite("p_D_tool_m", s.p_D_tool_m.data(), 3)) return "a non-finite " + *f;
  if (auto f = first_non_finite("v_D_tool_mps", s.v_D_tool_mps.data(), 3)) return "a non-finite " + *f;
  if (auto f = first_non_finite("q_D_tool_wxyz", s.q_D_tool_wxyz.data(), 4)) return "a non-finite " + *f;
  const std::array<double, 4>& q = s.q_D_tool_wxyz;
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (std::abs(n - 1.0) > 1e-3) return fmt::format("q_D_tool_wxyz of norm {}, not a unit quaternion", n);
  return std::nullopt;
}

DeviceCommand clamp_to_device(const DeviceInfo& info, const DeviceCommand& command) noexcept {
  DeviceCommand c = command;
  scale_to(c.force_D_N, info.max_force_N);
  if (info.dof_out == 6) {
    scale_to(c.torque_D_Nm, info.max_torque_Nm);
  } else {
    c.torque_D_Nm.fill(0.0);
  }
  return c;
}

double distance_outside_workspace_m(const DeviceInfo& info, const double* p_D_m) noexcept {
  double best = std::numeric_limits<double>::infinity();
  const std::uint32_t count = std::min<std::uint32_t>(info.workspace_box_count, static_cast<std::uint32_t>(DeviceInfo::kMaxWorkspaceBoxes));
  for (std::uint32_t b = 0; b < count; ++b) {
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double below = info.workspace[b].min_m[i] - p_D_m[i];
      const double above = p_D_m[i] - info.workspace[b].max_m[i];
      const double d = std::max({below, above, 0.0});
      d2 += d * d;
    }
    best = std::min(best, std::sqrt(d2));
  }
  return best;
}

}  // namespace mhd
