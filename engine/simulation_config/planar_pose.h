#pragma once
// A pose on the floor of a simulated session.

namespace mhd::simulation {

/// A pose on the floor: position (x, z) and heading about +y.
struct PlanarPose {
  double x_m = 0.0;
  double z_m = 0.0;
  double heading_rad = 0.0;
};

}  // namespace mhd::simulation
