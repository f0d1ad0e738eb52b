#pragma once
// What a simulated tracker measures, read off the scene's simulated world
// (sim_world/sim_session.h) at the time its user was last moved to.

#include "sim_is900_model.h"
#include "simulation/simulated_world.h"

namespace mhd::sim_is900 {

[[nodiscard]] inline WorldTruth world_truth(const simulation::SimulatedWorld& world) {
  const simulation::PlanarPose base = world.base_pose();
  const simulation::HeadPose head = world.head();
  return {.base_x_m = base.x_m, .base_z_m = base.z_m, .base_heading_rad = base.heading_rad, .p_W_head = head.p_W_m,
          .q_W_head = head.q_W};
}

}  // namespace mhd::sim_is900
