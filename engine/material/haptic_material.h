#pragma once
// Haptic surface properties, SI units.

namespace mhd {

struct HapticMaterial {
  double stiffness_N_per_m = 1000.0;
  /// Damps the HIP's velocity along the contact normal while in contact.
  double damping_Ns_per_m = 0.0;
  /// Friction coefficients (friction cone half-angle = atan(mu)); static >= dynamic.
  double static_friction = 0.0;
  double dynamic_friction = 0.0;
  /// Interpolate vertex normals across triangles for the force direction.
  bool force_shading = false;
};

}  // namespace mhd
