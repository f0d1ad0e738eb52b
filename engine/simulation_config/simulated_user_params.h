#pragma once
// The scene's <simulated_user> block as a SimulatedUserConfig. Parameters (SI, unit in
// the name): path ("x z speed; ..."), loop_path, seed, start_x_m, start_z_m,
// start_heading_deg, max_speed_mps, walk_speed_min_mps, walk_speed_max_mps,
// side_step_probability, stand_probability, side_step_speed_max_mps, area_half_size_m,
// eye_height_m, hand_reach_m, hand_height_m, hand_motion_amplitude_m, gaze_target_m
// ("x y z"). See docs/simulation.md for what each does.

#include "diagnostics/result.h"
#include "scene/scene_description.h"
#include "simulation_config/simulated_user_config.h"

#include <optional>

namespace mhd::simulation {

/// Reads and checks every parameter (each error at its param's file:line), and checks
/// the whole configuration as SimulatedUser would.
[[nodiscard]] Result<SimulatedUserConfig> simulated_user_config_from(const ParamBlock& block);

}  // namespace mhd::simulation
