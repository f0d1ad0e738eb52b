#include "proxy/force_shading.h"

#include "proxy/constraint_projection.h"

#include <array>
#include <span>

namespace mhd::proxy_detail {
namespace {

// A shaded goal nearer the contact than this (fraction of the skin) changes nothing
// a hand could feel, and a second pass for it would only cost sweeps.
constexpr double kMinShadingStepPerSkin = 1e-3;
// The shaded planes may be violated by this much (fraction of the skin) in the projection.
constexpr double kShadedTolerancePerSkin = 1e-3;

}  // namespace

std::optional<Eigen::Vector3d> shaded_goal_W(const CollisionWorld& world, const ProxyState& state,
                                             const Eigen::Vector3d& contact_W, const Eigen::Vector3d& p_W_hip,
                                             double skin_m) {
  std::array<HalfSpace, kMaxConstraintPlanes> shaded{};
  bool hip_behind = false;
  for (int i = 0; i < state.plane_count; ++i) {
    const ConstraintPlane& plane = state.planes[static_cast<std::size_t>(i)];
    hip_behind = hip_behind || plane.normal_W.dot(p_W_hip) < plane.offset_m - skin_m;
    Eigen::Vector3d n = world.shaded_normal_W(plane.triangle, contact_W);
    // The plane's normal points to the side the proxy is on; a two-sided surface may be
    // touched from behind its winding.
    if (n.dot(plane.normal_W) < 0.0) n = -n;
    if (!(n.squaredNorm() > 0.0)) n = plane.normal_W;  // degenerate triangle: unshaded
    shaded[static_cast<std::size_t>(i)] = HalfSpace{n, n.dot(contact_W)};
  }
  if (!hip_behind) return std::nullopt;
  const auto goal = project_onto_half_spaces(
      p_W_hip, std::span<const HalfSpace>(shaded.data(), static_cast<std::size_t>(state.plane_count)),
      kShadedTolerancePerSkin * skin_m);
  if (!goal || (*goal - contact_W).norm() <= kMinShadingStepPerSkin * skin_m) return std::nullopt;
  return goal;
}

bool hip_hidden_by_contact(const CollisionWorld& world, const ProxyState& state, const Eigen::Vector3d& p_W,
                           const Eigen::Vector3d& p_W_hip) {
  for (int i = 0; i < state.plane_count; ++i) {
    const TriangleRef& t = state.planes[static_cast<std::size_t>(i)].triangle;
    if (t.triangle == kExactSurface) {  // hidden when the HIP is inside the solid
      if (!world.support_plane(t.object, p_W_hip)) return true;
      continue;
    }
    const auto v = world.triangle_W(t);
    const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
    const double from = n.dot(p_W - v[0]);
    const double to = n.dot(p_W_hip - v[0]);
    if (!((from > 0.0 && to < 0.0) || (from < 0.0 && to > 0.0))) continue;
    const Eigen::Vector3d through = p_W + (from / (from - to)) * (p_W_hip - p_W);
    if (world.projects_onto_triangle(t, through, 0.0)) return true;
  }
  return false;
}

}  // namespace mhd::proxy_detail
