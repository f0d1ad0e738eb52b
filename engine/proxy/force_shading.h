#pragma once
// Two-pass force shading (Ruspini, Kolarov & Khatib 1997, "The haptic display of complex
// graphical environments", section 5). First pass: the ordinary god-object gives the
// contact point; each plane the proxy rests on is replaced by the plane through that
// point with the normal interpolated over its triangle, and the HIP projected onto those
// shaded planes is the shaded goal. Second pass: the god-object runs again towards that
// goal, held by the real surface, so the proxy ends on the real surface where the
// shaded surface would put it, and its force turns smoothly over a coarse tessellation.
// The goal is only a goal: the real constraints filter it, and the contract of
// docs/proxy.md holds. Internal to the proxy library; step_proxy() is the API.

#include "collision/collision_world.h"
#include "proxy/god_object.h"

#include <Eigen/Core>

#include <optional>

namespace mhd::proxy_detail {

/// The shaded goal of the first pass, from the planes in `state` (those the proxy rests
/// on at `contact_W`). Nullopt when shading has nothing to do: no plane, the HIP not
/// behind a plane, or a goal within a thousandth of a skin of the contact (a flat face,
/// or an edge sharper than the crease angle, whose interpolated normals are the faces').
[[nodiscard]] std::optional<Eigen::Vector3d> shaded_goal_W(const CollisionWorld& world, const ProxyState& state,
                                                           const Eigen::Vector3d& contact_W,
                                                           const Eigen::Vector3d& p_W_hip, double skin_m);

/// True when the straight segment from the proxy at p_W to the HIP passes through one of
/// the triangles of the planes in `state`: the HIP is then out of the proxy's sight, so a
/// force is due (docs/proxy.md, follow failures). False says only "not shown here".
[[nodiscard]] bool hip_hidden_by_contact(const CollisionWorld& world, const ProxyState& state,
                                         const Eigen::Vector3d& p_W, const Eigen::Vector3d& p_W_hip);

}  // namespace mhd::proxy_detail
