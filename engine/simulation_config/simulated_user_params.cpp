#include "simulation_config/simulated_user_params.h"

#include "scene/param_block_reader.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace mhd::simulation {

Result<SimulatedUserConfig> simulated_user_config_from(const ParamBlock& block) {
  constexpr double kDegToRad = std::numbers::pi / 180.0;
  ParamBlockReader r(&block, "<simulated_user>");
  SimulatedUserConfig c;
  if (r.has("path")) {
    try {
      c.path = parse_waypoints(r.text("path", ""));
    } catch (const std::invalid_argument& e) {
      r.error("path", std::string("param 'path' in <simulated_user>: ") + e.what());
    }
  }
  c.loop_path = r.boolean("loop_path", c.loop_path);
  c.seed = r.unsigned_integer("seed", c.seed);
  c.start.x_m = r.number("start_x_m", c.start.x_m);
  c.start.z_m = r.number("start_z_m", c.start.z_m);
  c.start.heading_rad = r.number("start_heading_deg", c.start.heading_rad / kDegToRad) * kDegToRad;
  c.max_speed_mps = r.positive("max_speed_mps", c.max_speed_mps);
  c.walk_speed_min_mps = r.non_negative("walk_speed_min_mps", c.walk_speed_min_mps);
  c.walk_speed_max_mps = r.non_negative("walk_speed_max_mps", c.walk_speed_max_mps);
  c.side_step_probability = r.fraction("side_step_probability", c.side_step_probability);
  c.stand_probability = r.fraction("stand_probability", c.stand_probability);
  c.side_step_speed_max_mps = r.non_negative("side_step_speed_max_mps", c.side_step_speed_max_mps);
  c.area_half_size_m = r.positive("area_half_size_m", c.area_half_size_m);
  c.eye_height_m = r.positive("eye_height_m", c.eye_height_m);
  c.hand_reach_m = r.non_negative("hand_reach_m", c.hand_reach_m);
  c.hand_height_m = r.positive("hand_height_m", c.hand_height_m);
  c.hand_motion_amplitude_m = r.non_negative("hand_motion_amplitude_m", c.hand_motion_amplitude_m);
  // The sweep's speed and hold are read (and judged) whether or not a sweep is set.
  HandHeightSweep sweep;
  sweep.speed_mps = r.positive("hand_height_sweep_speed_mps", sweep.speed_mps);
  sweep.hold_s = r.non_negative("hand_height_sweep_hold_s", sweep.hold_s);
  if (r.has("hand_height_sweep_m")) {
    std::istringstream in(r.text("hand_height_sweep_m", ""));
    std::string rest;
    if (!(in >> sweep.low_m >> sweep.high_m) || (in >> rest) || !std::isfinite(sweep.low_m) ||
        !std::isfinite(sweep.high_m)) {
      r.error("hand_height_sweep_m", "param 'hand_height_sweep_m' in <simulated_user> must be two heights 'low high'");
    }
    c.hand_height_sweep = sweep;
  }
  if (r.has("gaze_target_m")) {
    std::istringstream in(r.text("gaze_target_m", ""));
    Eigen::Vector3d g;
    std::string rest;
    if (!(in >> g.x() >> g.y() >> g.z()) || (in >> rest) || !g.allFinite()) {
      r.error("gaze_target_m", "param 'gaze_target_m' in <simulated_user> must be three numbers 'x y z'");
    } else {
      c.gaze_target_W = g;
    }
  }
  Diagnostics errors = r.finish();
  if (!errors.empty()) return errors;
  try {
    validate(c);  // the whole configuration, as SimulatedUser checks it
  } catch (const std::invalid_argument& e) {
    return Diagnostic{block.where, std::string("<simulated_user>: ") + e.what()};
  }
  return c;
}

}  // namespace mhd::simulation
