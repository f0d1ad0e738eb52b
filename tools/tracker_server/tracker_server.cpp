#include "tracker_server/tracker_server.h"

#include "dds_common/dds_convert.h"
#include "dds_common/dds_topics.h"
#include "dds_common/shared_sim_world.h"
#include "plugin_host/abi_conversion.h"
#include "plugin_host/host_services.h"
#include "plugin_host/open_plugin.h"
#include "plugin_host/plugin_search_path.h"
#include "scene_xml/scene_reader.h"
#include "simulation/simulated_user.h"
#include "simulation_config/simulated_user_params.h"
#include "simulation/simulated_world.h"
#include "sim_world/sim_session.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <thread>

namespace mhd::dds {
namespace {

SceneDescription read_scene(const std::filesystem::path& file) {
  Result<SceneDescription> read = read_scene_file(file);
  if (!read.ok()) {
    std::string message;
    for (const Diagnostic& d : read.diagnostics()) {
      if (!message.empty()) message += '\n';
      message += d.to_string();
    }
    throw TrackerServerSceneError(message);
  }
  return std::move(*read);
}

PluginDescription tracker_of(const SceneDescription& scene, const std::filesystem::path& file,
                             const TrackerServerOptions& options) {
  std::vector<const PluginDescription*> trackers;
  for (const PluginDescription& p : scene.plugins) {
    if (p.kind == PluginKind::Tracker) trackers.push_back(&p);
  }
  if (trackers.size() != 1) {
    throw TrackerServerError(fmt::format("{}: the scene names {} tracker plugins, the tracker server needs one",
                                         file.string(), trackers.size()));
  }
  PluginDescription tracker = *trackers.front();
  // Any plugin gets an explicit rate (one that has none refuses the unknown parameter).
  if (options.rate_hz) {
    tracker.params["rate_hz"] = fmt::format("{}", *options.rate_hz);
  } else if (tracker.name == "sim_is900" && tracker.params.count("rate_hz") == 0) {
    tracker.params["rate_hz"] = fmt::format("{}", TrackerServerOptions::kDefaultRateHz);
  }
  return tracker;
}

[[noreturn]] void fail(const PluginError& error) { throw TrackerServerError(error.to_string()); }

}  // namespace

TrackerServerReport run_tracker_server(const TrackerServerOptions& options, const std::atomic<bool>& stop,
                                       const std::function<void(const std::string&)>& on_started) {
  if (!(options.poll_period_s > 0.0)) throw TrackerServerError("the poll period must be positive");
  if (options.rate_hz && !(*options.rate_hz > 0.0)) throw TrackerServerError("--rate-hz must be positive");
  const SceneDescription scene = read_scene(options.scene_file);
  const PluginDescription description = tracker_of(scene, options.scene_file, options);

  // Not shared: the scene's <simulated_user> when it has one, else a random walk seeded
  // by --seed. Shared: the haptic server's user and base, received below.
  std::optional<simulation::SimulatedUserConfig> user_config;
  if (!options.shared_world) {
    user_config.emplace();
    user_config->seed = options.user_seed;
    if (scene.simulated_user) {
      auto parsed = simulation::simulated_user_config_from(*scene.simulated_user);
      if (!parsed.ok()) throw TrackerServerError(parsed.error().front().to_string());
      user_config = std::move(parsed).value();
    }
  }
  HostServices host;
  host.set_scene_file(std::filesystem::absolute(options.scene_file));
  // The world the simulated tracker plugin will find (the same session: same scene, same
  // process); it moves the user itself.
  const std::shared_ptr<sim_world::SimSession> session = sim_world::SimSession::acquire(host.abi());
  session->set_user(std::move(user_config), host.now_s());
  simulation::SimulatedWorld& world = session->world();

  const PluginSearchPath search = PluginSearchPath::standard(options.plugin_paths);
  Result<PluginInstance, PluginError> opened = open_plugin(search, description, host.abi());
  if (!opened) fail(opened.error());
  PluginInstance& tracker = opened.value();

  const Participant participant(options.domain_id, {}, options.identity_dir);
  Publisher<mhd_dds_TrackerSample> publisher(participant, rig_partition(options.rig_id), options.ownership_strength);

  TrackerServerReport report;
  report.plugin = tracker.name();
  // The duration counts from here, the wait for a shared world included.
  const double t0_s = host.now_s();
  std::optional<SimWorldSubscriber> shared;
  if (options.shared_world) {
    shared.emplace(participant, options.rig_id);
    while (!shared->apply_newest(world)) {
      if (stop.load(std::memory_order_relaxed) ||
          (options.duration_s && host.now_s() - t0_s >= *options.duration_s)) {
        report.elapsed_s = host.now_s() - t0_s;
        report.world_states_rejected = shared->rejected();
        if (Status<PluginError> closed = tracker.close(); !closed) fail(closed.error());
        return report;
      }
      (void)shared->wait(DDS_MSECS(50));
    }
  }

  if (Status<PluginError> started = tracker.start(); !started) fail(started.error());
  if (on_started) {
    on_started(fmt::format("tracker '{}' publishing rig {} on DDS (partition {}, ownership strength {}, {}){}",
                           tracker.name(), options.rig_id, rig_partition(options.rig_id), options.ownership_strength,
                           participant.secured() ? "secured as " + participant.identity_dir().string()
                                                 : std::string("unsecured"),
                           shared ? ", measuring the simulated world the rig's haptic server publishes" : ""));
  }

  std::array<TrackerSample, 64> samples{};
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(options.poll_period_s));
  auto next = std::chrono::steady_clock::now();
  while (!stop.load(std::memory_order_relaxed)) {
    const double now_s = host.now_s();
    if (options.duration_s && now_s - t0_s >= *options.duration_s) break;
    if (shared) (void)shared->apply_newest(world);
    if (tracker.simulates()) {
      if (auto r = tracker.simulate_until(now_s); !r) fail(r.error());
    }
    for (;;) {
      std::size_t count = 0;
      auto r = tracker.tracker_read(samples, count);
      if (!r) fail(r.error());
      if (r.value() == PluginCallStatus::Deactivate) throw TrackerServerError("the tracker asks to be stopped");
      const double host_now_s = host.now_s();
      const std::int64_t now_ns = realtime_ns();
      for (std::size_t i = 0; i < count; ++i) {
        publisher.write(to_dds(to_abi(samples[i]), options.rig_id,
                               realtime_from_host(samples[i].timestamp_s, host_now_s, now_ns)));
      }
      report.published += count;
      if (count < samples.size()) break;
    }
    next += period;
    const auto now = std::chrono::steady_clock::now();
    if (next < now) next = now;  // late: do not try to catch up
    std::this_thread::sleep_until(next);
  }
  report.elapsed_s = host.now_s() - t0_s;
  if (shared) {
    report.world_states = shared->applied();
    report.world_states_rejected = shared->rejected();
  }
  if (Status<PluginError> stopped = tracker.close(); !stopped) fail(stopped.error());
  return report;
}

}  // namespace mhd::dds
