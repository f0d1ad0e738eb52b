#include "sim_world/sim_session.h"

#include "scene_xml/scene_reader.h"
#include "simulation_config/simulated_user_params.h"

#include "realtime/periodic_timer.h"
#include "realtime/thread_name.h"

#include <map>
#include <stdexcept>
#include <utility>

namespace mhd::sim_world {
namespace {

// Every live session of this process, by scene file. Weak: a session ends with its last
// holder, so a later run of the same scene starts from a fresh world.
std::mutex g_registry_mutex;
std::map<std::string, std::weak_ptr<SimSession>>& registry() {
  static std::map<std::string, std::weak_ptr<SimSession>> sessions;
  return sessions;
}

std::string joined(const std::vector<Diagnostic>& errors) {
  std::string text;
  for (const Diagnostic& d : errors) text += (text.empty() ? "" : "\n") + d.to_string();
  return text;
}

/// The scene's <simulated_user>, or none when there is no scene or it has no such block.
std::optional<simulation::SimulatedUserConfig> scene_user(const std::string& scene_file) {
  if (scene_file.empty()) return std::nullopt;
  Result<SceneDescription> scene = read_scene_file(scene_file);
  if (!scene.ok()) throw std::runtime_error("the simulated world's scene: " + joined(scene.error()));
  if (!scene->simulated_user) return std::nullopt;
  Result<simulation::SimulatedUserConfig> user = simulation::simulated_user_config_from(*scene->simulated_user);
  if (!user.ok()) throw std::runtime_error("the simulated world's <simulated_user>: " + joined(user.error()));
  return std::move(user).value();
}

}  // namespace

std::shared_ptr<SimSession> SimSession::acquire(const mhd_host& host) {
  return acquire(host.scene_file != nullptr ? host.scene_file : "", host.now_s(host.clock_context));
}

std::shared_ptr<SimSession> SimSession::acquire(const std::string& scene_file, double now_s) {
  const std::lock_guard lock(g_registry_mutex);
  // Forget the sessions that ended, so the registry does not grow.
  std::erase_if(registry(), [](const auto& entry) { return entry.second.expired(); });
  std::weak_ptr<SimSession>& slot = registry()[scene_file];
  if (std::shared_ptr<SimSession> live = slot.lock()) return live;
  std::shared_ptr<SimSession> made(new SimSession());
  made->set_user(scene_user(scene_file), now_s);
  slot = made;
  return made;
}

SimSession::~SimSession() = default;

std::unique_ptr<UserRunner> SimSession::run_user(const std::shared_ptr<SimSession>& session, const mhd_host& host,
                                                 double period_s) {
  if (!session->has_user()) return nullptr;
  return std::make_unique<UserRunner>(session, host, period_s);
}

UserRunner::UserRunner(std::shared_ptr<SimSession> session, const mhd_host& host, double period_s)
    : session_(std::move(session)) {
  thread_ = std::thread([this, now_s = host.now_s, clock = host.clock_context, period_s] {
    realtime::name_current_thread("mhd-sim-user");
    realtime::PeriodicTimer timer(period_s);
    while (!stop_.load(std::memory_order_relaxed)) {
      session_->advance_to(now_s(clock));
      (void)timer.wait_next();
    }
  });
}

UserRunner::~UserRunner() {
  stop_.store(true, std::memory_order_relaxed);
  thread_.join();
}

void SimSession::advance_to(double t_s) noexcept {
  const std::unique_lock lock(user_mutex_, std::try_to_lock);
  if (!lock.owns_lock() || !user_ || t_s <= user_->time_s()) return;
  user_->update(t_s, world_);
}

void SimSession::set_user(std::optional<simulation::SimulatedUserConfig> config, double now_s) {
  const std::lock_guard lock(user_mutex_);
  user_.reset();
  if (config) {
    user_.emplace(std::move(*config));
    user_->update(now_s, world_);
  }
  has_user_.store(user_.has_value(), std::memory_order_release);
}

}  // namespace mhd::sim_world
