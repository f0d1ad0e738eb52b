#pragma once
// The simulated world of one scene, shared by the simulated plugins a process opens for
// it (device, tracker, base, and the dds tracker that publishes the world), and the
// scene's <simulated_user>, who moves in it. Simulation is not the host's business: the
// plugin ABI carries no world, so the plugins find each other's here, by the scene file
// the host runs (mhd_host::scene_file; a host with none shares the world of "no scene").
//
// The user moves when a plugin asks for the world at a time (advance_to: the tracker and
// the dds publisher, on the host's io thread), and on a thread of the session while a
// device holds a UserRunner (a device's calls run on the haptic thread, which must never
// lock, and on a desk no other plugin moves the user). Its state at a time does not
// depend on how often it was advanced (simulation/simulated_user.h), so all of them may
// move it; advance_to never waits: a thread that finds another moving the user leaves
// it to that one and reads the world (lock-free) as it is.
//
// This is a shared library (libmhd_sim_world.so), so a process holds one registry,
// whichever plugins load it.

#include "simulation/simulated_user.h"
#include "simulation/simulated_world.h"

#include <mhd/plugin_abi.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#define MHD_SIM_WORLD_API __attribute__((visibility("default")))

namespace mhd::sim_world {

class SimSession;

/// While it lives, a thread moves the session's user to the host's now every period.
class MHD_SIM_WORLD_API UserRunner {
 public:
  UserRunner(std::shared_ptr<SimSession> session, const mhd_host& host, double period_s);
  UserRunner(const UserRunner&) = delete;
  UserRunner& operator=(const UserRunner&) = delete;
  UserRunner(UserRunner&&) = delete;
  UserRunner& operator=(UserRunner&&) = delete;
  /// Stops and joins the thread.
  ~UserRunner();

 private:
  std::shared_ptr<SimSession> session_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

class MHD_SIM_WORLD_API SimSession {
 public:
  /// The session of the scene `host` runs, made by the first plugin to ask (the scene's
  /// <simulated_user> read and moved to the host's now) and kept while anyone holds it.
  /// Throws std::runtime_error with the scene's file:line errors when the scene cannot
  /// be read or its <simulated_user> is invalid.
  [[nodiscard]] static std::shared_ptr<SimSession> acquire(const mhd_host& host);
  /// The same by scene file (empty: no scene), the user placed at host time now_s: for
  /// tools that host simulated plugins and set the world up before opening them.
  [[nodiscard]] static std::shared_ptr<SimSession> acquire(const std::string& scene_file, double now_s);

  SimSession(const SimSession&) = delete;
  SimSession& operator=(const SimSession&) = delete;
  SimSession(SimSession&&) = delete;
  SimSession& operator=(SimSession&&) = delete;
  ~SimSession();

  /// The world itself: readers are lock-free (simulated_world.h).
  [[nodiscard]] simulation::SimulatedWorld& world() noexcept { return world_; }
  /// Whether a user moves head and hand; without one they stay where they were written.
  [[nodiscard]] bool has_user() const noexcept { return has_user_.load(std::memory_order_acquire); }

  /// Moves the user to host time t_s and writes head and hand. A time not after the
  /// user's, or another thread moving the user now, leaves the world as it is. Never blocks.
  void advance_to(double t_s) noexcept;

  /// Replaces the scene's user (nullopt: nobody moves head and hand, the world is written
  /// from outside) and moves the new one to now_s. Throws std::invalid_argument for an
  /// invalid configuration. Call before the plugins start.
  void set_user(std::optional<simulation::SimulatedUserConfig> config, double now_s);

  /// A thread that moves the user to host time (`host`'s clock, which must outlive the
  /// runner) every period_s, until the runner is dropped: what a simulated device holds
  /// from start to stop. Null when the session has no user (nothing to move).
  [[nodiscard]] static std::unique_ptr<UserRunner> run_user(const std::shared_ptr<SimSession>& session,
                                                            const mhd_host& host, double period_s = 1e-3);

 private:
  SimSession() = default;

  simulation::SimulatedWorld world_;
  std::mutex user_mutex_;
  std::optional<simulation::SimulatedUser> user_;  ///< under user_mutex_
  std::atomic<bool> has_user_{false};
};

}  // namespace mhd::sim_world
