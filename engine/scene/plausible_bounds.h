#pragma once
// The ranges a scene's settings must fall within; outside them the reader refuses the
// scene at the value's file:line (docs/scene-format.md, "Plausible values").

namespace mhd {

/// Haptic loop rate: below 500 Hz a contact is felt as a buzz and each torque is held
/// too long; above 20 kHz no PHANToM-class device or host loop keeps up.
inline constexpr double kMinHapticRate_Hz = 500.0;
inline constexpr double kMaxHapticRate_Hz = 20'000.0;

/// SensAble's nominal stiffness for the Premium 1.5 (3.5 N/mm) holds at the 1 kHz loop it
/// was rated with. Colgate & Schenkel's passivity condition b > K T / 2 + |B| makes the
/// stable stiffness proportional to the rate (K < 2 b / T), so the bound scales with it.
inline constexpr double kNominalStiffness_N_per_m = 3500.0;
inline constexpr double kNominalStiffnessRate_Hz = 1000.0;

/// Highest stiffness the device renders stably at `rate_Hz`.
[[nodiscard]] constexpr double max_stable_stiffness_N_per_m(double rate_Hz) noexcept {
  return kNominalStiffness_N_per_m * rate_Hz / kNominalStiffnessRate_Hz;
}

/// At 100 N s/m a hand moving 8.5 cm/s already meets the peak force: more only clamps.
inline constexpr double kMaxDamping_Ns_per_m = 100.0;

/// Friction coefficients (static and dynamic): rubber on rubber is about 1 to 2.
inline constexpr double kMaxFriction = 2.0;

/// Texture depth (docs/textures.md): at the stiffest material (3.5 N/mm) 5 mm of relief is
/// already twice the force clamp; deeper relief is a shape, to be modelled as geometry.
inline constexpr double kMaxTextureDepth_m = 0.005;
/// Texture periods and image sizes: 0.1 mm is a 1 kHz vibration at 0.1 m/s, the haptic
/// rate itself (finer aliases); beyond 1 m a surface has no texture a hand feels as one.
inline constexpr double kMinTexturePeriod_m = 1e-4;
inline constexpr double kMaxTexturePeriod_m = 1.0;
/// Force shading's crease angle, degrees: two normals never differ by more.
inline constexpr double kMaxCreaseAngle_deg = 180.0;

/// Object and rig-frame positions, |p| in metres: a lab-sized rig, generously.
inline constexpr double kMaxPosition_m = 1000.0;

}  // namespace mhd
