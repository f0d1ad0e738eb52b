#include "viewer/demo_state.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace mhd::viewer {
namespace {

/// The parameter as a number; `fallback` when absent or not a number.
double param_number(const PluginDescription& plugin, const std::string& name, double fallback) {
  const auto it = plugin.params.find(name);
  if (it == plugin.params.end()) return fallback;
  double v = 0.0;
  const std::string& s = it->second;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(v) ? v : fallback;
}

}  // namespace

RigState demo_rig_state(const ViewerScene& scene, const std::optional<BasePose>& base) {
  RigState s;
  for (const PluginDescription& p : scene.scene.plugins) {
    if (p.kind != PluginKind::Base || p.name != "sim_omni3") continue;
    s.base.x_m = param_number(p, "x_m", 0.0);
    s.base.z_m = param_number(p, "z_m", 0.0);
    s.base.heading_rad = param_number(p, "heading_deg", 0.0) * std::numbers::pi / 180.0;
  }
  if (base) s.base = *base;
  if (scene.rig) {
    const Pose X_W_phantom = scene.rig->X_W_phantom(scene.rig->X_W_robot_from_base(s.base));
    s.p_W_hip_m = X_W_phantom * scene.rig->device().usable_workspace().center_P_m();
  } else {
    const Eigen::Vector3d forward(std::cos(s.base.heading_rad), 0.0, -std::sin(s.base.heading_rad));
    s.p_W_hip_m = Eigen::Vector3d(s.base.x_m, 1.0, s.base.z_m) + 0.5 * forward;
  }
  // Lifted off the object towards the user, so the HIP and the arm are in view.
  s.p_W_hip_m += Eigen::Vector3d(0.0, 0.08, 0.15);
  s.p_W_proxy_m = s.p_W_hip_m;
  s.in_contact = false;
  s.X_W_head = head_looking_at(s.p_W_hip_m + Eigen::Vector3d(0.0, 0.5, 0.7), s.p_W_hip_m);
  return s;
}

}  // namespace mhd::viewer
