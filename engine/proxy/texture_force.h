#pragma once
// Haptic textures on top of the god-object's force (docs/textures.md). The proxy moves
// over the real, smooth surface and never crosses it (docs/proxy.md); a texture only
// shapes the force computed from it: the surface height and normal by the texture's
// height field (Minsky et al. 1990; Ho, Basdogan & Srinivasan 1999), and the friction
// coefficients by its friction map. Allocation-free, for the haptic tick.

#include "collision/collision_world.h"
#include "material/haptic_material.h"

namespace mhd {

/// Factor on `material`'s friction coefficients with the proxy at p_W on `object`:
/// 1 without a texture, else the texture's friction_scale there.
[[nodiscard]] double texture_friction_scale(const CollisionWorld& world, const HapticMaterial& material, int object,
                                            const Eigen::Vector3d& p_W);

/// The contact force `force_W` (the spring's, pulling the HIP to the proxy at p_W on
/// `object`, whose surface normal is n_W, unit, towards free space) as the textured
/// surface renders it. Its normal part becomes max(0, f.n + k h), the spring compressed
/// by the texture's height h <= 0 under the proxy, and points along the textured surface's
/// normal, n - grad h normalised (grad h in the tangent plane); its tangential part (the
/// friction) is kept. So the normal force never exceeds the smooth surface's, and a
/// texture adds no force where the smooth surface gives none. Without a texture it
/// returns force_W unchanged.
[[nodiscard]] Eigen::Vector3d textured_force(const CollisionWorld& world, const HapticMaterial& material, int object,
                                             const Eigen::Vector3d& p_W, const Eigen::Vector3d& n_W,
                                             const Eigen::Vector3d& force_W);

}  // namespace mhd
