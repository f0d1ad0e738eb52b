#include "proxy/texture_force.h"

#include <algorithm>

namespace mhd {
namespace {

TextureSample sample_at(const CollisionWorld& world, const HapticTexture& texture, int object,
                        const Eigen::Vector3d& p_W) {
  // Textures live in the object's frame, so they move with it.
  const Eigen::Vector3d p_O = world.pose(object).inverse(Eigen::Isometry) * p_W;
  return texture.sample(texture.uv_of(p_O));
}

bool has_texture(const CollisionWorld& world, const HapticMaterial& material, int object) {
  return material.texture != nullptr && object >= 0 && object < world.object_count();
}

}  // namespace

double texture_friction_scale(const CollisionWorld& world, const HapticMaterial& material, int object,
                              const Eigen::Vector3d& p_W) {
  if (!has_texture(world, material, object)) return 1.0;
  // Skip the sample (24 sinusoids for noise) where the scale cannot matter.
  const bool frictionless = material.static_friction == 0.0 && material.dynamic_friction == 0.0;
  if (frictionless || material.texture->spec().friction_contrast == 0.0) return 1.0;
  return sample_at(world, *material.texture, object, p_W).friction_scale;
}

Eigen::Vector3d textured_force(const CollisionWorld& world, const HapticMaterial& material, int object,
                               const Eigen::Vector3d& p_W, const Eigen::Vector3d& n_W,
                               const Eigen::Vector3d& force_W) {
  if (!has_texture(world, material, object)) return force_W;
  const HapticTexture& texture = *material.texture;
  const TextureSample s = sample_at(world, texture, object, p_W);
  const Eigen::Matrix3d& R_WO = world.pose(object).linear();
  const Eigen::Vector3d gradient_W =
      R_WO * (s.gradient_uv.x() * texture.u_axis_O() + s.gradient_uv.y() * texture.v_axis_O());
  const Eigen::Vector3d gradient_tangent_W = gradient_W - n_W * n_W.dot(gradient_W);
  const double normal_N = force_W.dot(n_W);
  const Eigen::Vector3d tangential_W = force_W - normal_N * n_W;
  // The HIP is `normal_N / k` behind the real surface, so `normal_N / k + h` behind the
  // textured one; a HIP in a valley's air gets no normal force.
  const double textured_normal_N = std::max(0.0, normal_N + material.stiffness_N_per_m * s.height_m);
  const Eigen::Vector3d n_textured_W = (n_W - gradient_tangent_W).normalized();
  return tangential_W + textured_normal_N * n_textured_W;
}

}  // namespace mhd
