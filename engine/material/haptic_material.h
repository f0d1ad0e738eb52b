#pragma once
// Haptic surface properties, SI units.

#include "material/haptic_texture.h"

#include <memory>
#include <optional>
#include <numbers>

namespace mhd {

struct HapticMaterial {
  double stiffness_N_per_m = 1000.0;
  /// Damps the HIP's velocity along the contact normal while in contact.
  double damping_Ns_per_m = 0.0;
  /// Friction coefficients (friction cone half-angle = atan(mu)); static >= dynamic.
  double static_friction = 0.0;
  double dynamic_friction = 0.0;
  /// Force shading (Ruspini, Kolarov & Khatib 1997): the proxy is drawn towards the HIP's
  /// foot on the plane with the normal interpolated over each triangle, so a coarse
  /// tessellation feels smooth; the real surface still holds it (docs/proxy.md).
  bool force_shading = false;
  /// The surface texture the scene describes (docs/textures.md); none for a smooth surface.
  std::optional<HapticTextureSpec> texture_spec;
  /// That texture, ready to sample at the haptic rate; built by the scene compiler (which
  /// reads height-map images). Null: the proxy renders the surface smooth.
  std::shared_ptr<const HapticTexture> texture;
  /// Under shading, faces whose normals differ by more than this keep a sharp edge (a
  /// cube's edges stay edges); 0 .. pi. Read when the scene is compiled.
  double force_shading_crease_rad = std::numbers::pi / 3.0;
};

}  // namespace mhd
