#pragma once
// The server's state at one moment, as the status line shows it while it runs and the
// report holds it at the end (ServerReport::status).

#include "haptic_server/plugin_counter.h"
#include "kinematics/base_pose.h"
#include "scene/scene_description.h"

#include <cstdint>
#include <vector>

namespace mhd {

struct ServerStatus {
  RigKind rig_kind = RigKind::Mobile;  ///< desktop: no tracker, no base (their fields stay empty)
  double elapsed_s = 0.0;
  std::uint64_t ticks = 0;
  double haptic_rate_hz = 0.0;  ///< over the last status interval (the report: over the run)
  std::uint64_t overruns = 0;
  bool in_contact = false;
  double force_N = 0.0;
  double safety_gain = 0.0;
  double tracker_age_s = 0.0;
  std::uint64_t tracker_samples = 0;
  std::uint64_t tracker_rejected = 0;  ///< dropped: wrong sensor, time from the future, sequence back
  std::vector<PluginCounter> tracker_plugin_counters;  ///< the tracker plugin's own (e.g. its drops)
  std::uint64_t early_ticks = 0;  ///< haptic ticks started at once by a new base-sensor sample
  BasePose base;
};

}  // namespace mhd
