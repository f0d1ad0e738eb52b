#pragma once
// `mhd tracker-server`: runs a scene's tracker plugin (sim_is900, replay, or real
// hardware) and publishes every sample it reads as mhd_dds::TrackerSample for one rig.
// For simulated trackers it sets up the scene's simulated world (libs/sim_world, the
// simulated plugins' own library) before opening the plugin: the scene's <simulated_user>
// or a random walk, which the plugin moves; the base stays where the world puts it (the
// base is the haptic server's). With shared_world it runs no user: it measures the world the rig's
// haptic server publishes (dds_common/shared_sim_world.h), so the simulated tracker sees
// the base the haptic server moves. The plugin is polled every poll_period_s, so a sample leaves at
// most one period after the plugin makes it readable.

#include "dds_common/dds_entity.h"
#include "dds_common/dds_topics.h"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd::dds {

class TrackerServerError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The scene did not read: what() is its diagnostics, one "FILE:LINE: error: ..." per line.
class TrackerServerSceneError : public TrackerServerError {
 public:
  using TrackerServerError::TrackerServerError;
};

struct TrackerServerOptions {
  std::filesystem::path scene_file;
  /// Given: the tracker's rate_hz parameter, overriding the scene's (a plugin without
  /// one, such as replay, refuses it). Not given: the scene's; sim_is900 without one in
  /// the scene gets kDefaultRateHz.
  std::optional<double> rate_hz;
  static constexpr double kDefaultRateHz = 190.0;
  std::optional<double> duration_s;  ///< run until stopped when not given
  std::uint32_t rig_id = 0;
  dds_domainid_t domain_id = DDS_DOMAIN_DEFAULT;
  std::vector<std::filesystem::path> plugin_paths;  ///< --plugin-path, searched first
  std::uint64_t user_seed = 0;                      ///< the simulated user's random walk
  double poll_period_s = 0.001;
  /// DDS Security identity folder (participant_security.h); not given: $MHD_DDS_IDENTITY,
  /// else unsecured.
  std::optional<std::filesystem::path> identity_dir;
  /// The samples' writer strength under exclusive ownership: a second tracker server
  /// for the same rig must have a different one, and only the stronger is heard.
  std::int32_t ownership_strength = kDefaultOwnershipStrength;
  /// Measure rig rig_id's simulated world as its haptic server publishes it (the dds
  /// tracker's publish_sim_world) instead of a user of this process (the scene's
  /// <simulated_user> and user_seed are then unused). The tracker starts on the first
  /// world received: before it there is no base to measure. duration_s includes the wait.
  bool shared_world = false;
};

struct TrackerServerReport {
  std::string plugin;           ///< the tracker plugin's name
  std::uint64_t published = 0;  ///< samples written to DDS
  /// shared_world: polls that took a new world state (the newest of those arrived), and
  /// states refused (another rig, not finite, a quaternion that does not normalise).
  std::uint64_t world_states = 0, world_states_rejected = 0;
  double elapsed_s = 0.0;
};

/// Runs until `stop` is set or the duration has passed. Throws TrackerServerSceneError
/// for a scene that does not read, TrackerServerError for one without exactly one
/// tracker plugin ("FILE: the scene names 0 tracker plugins, ...") and a plugin that
/// does not load, open, start or read (its PluginError's text), DdsError for DDS.
/// `on_started` (may be empty) is called once the plugin runs and the writer exists
/// (with shared_world, once the first world has arrived; a stop or the duration
/// before that ends the run with nothing published).
TrackerServerReport run_tracker_server(const TrackerServerOptions& options, const std::atomic<bool>& stop,
                                       const std::function<void(const std::string&)>& on_started = {});

}  // namespace mhd::dds
