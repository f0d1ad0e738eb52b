#pragma once
// What makes a scene object pushable (<dynamics>, docs/scene-format.md "Pushable
// objects"): its mass and its Coulomb friction with the still objects it rests on. Plain
// data; engine/dynamics simulates it.

namespace mhd {

struct ObjectDynamics {
  double mass_kg = 1.0;
  /// Coulomb friction coefficient against still objects (the floor, a table): a resting
  /// body slides once the push along the surface exceeds friction * normal load.
  double friction = 0.5;
};

}  // namespace mhd
