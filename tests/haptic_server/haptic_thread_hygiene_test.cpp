// No mutex, allocation or I/O on the haptic thread, and no mutex or allocation on the io
// thread, in the whole server on simulated hardware: sim_phantom, sim_is900 and sim_omni3
// logging their commands, the predictive planner following a simulated user, a recording
// and a display.
//
// haptic_thread_watch.cpp interposes pthread_mutex_lock, operator new, write and fwrite
// for this binary, counting the calls made on one named thread: a mutex, an allocation or
// a write that appears there, in the engine or in a plugin, fails the test. The first test
// is the control: the counters see a thread of that name lock, allocate and write.
// Not run under the sanitizers (they replace these functions themselves).

#include "haptic_thread_watch.h"

#include "haptic_server/haptic_server.h"
#include "haptic_server/tracker_sample_filter.h"
#include "realtime/thread_name.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>
#include <fmt/core.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace mhd;

using test::ThreadCalls;

/// What the thread named `thread_name` did between from_s and to_s after the call, while
/// `body` runs.
template <class Body>
ThreadCalls count_while(const char* thread_name, double from_s, double to_s, Body&& body) {
  ThreadCalls calls;
  std::thread window([&] {
    std::this_thread::sleep_for(std::chrono::duration<double>(from_s));
    test::start_thread_watch(thread_name);
    std::this_thread::sleep_for(std::chrono::duration<double>(to_s - from_s));
    calls = test::stop_thread_watch();
  });
  body();
  window.join();
  return calls;
}

TEST(HapticThreadHygiene, TheCountersSeeAThreadOfThatNameLockAllocateAndWrite) {
  const ThreadCalls c = count_while(realtime::kHapticThreadName, 0.0, 0.3, [] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::thread haptic([] {
      realtime::name_current_thread(realtime::kHapticThreadName);
      std::mutex m;
      { const std::lock_guard lock(m); }
      auto* volatile p = new std::vector<int>(1000);
      delete p;
      const char text[] = "x";
      std::FILE* f = std::fopen("/dev/null", "w");
      ASSERT_NE(f, nullptr);
      (void)std::fwrite(text, 1, 1, f);
      std::fclose(f);
      (void)::write(-1, text, 1);
    });
    haptic.join();
    std::thread other([] {  // and nothing from another thread
      std::mutex m;
      { const std::lock_guard lock(m); }
      delete new int(3);
    });
    other.join();
  });
  EXPECT_GE(c.locks, 1);
  EXPECT_GE(c.allocations, 2);
  EXPECT_GE(c.writes, 2);
}

// The io thread's check of every tracker sample keeps its memory in place: a tracker that
// names a new sensor in each sample (10,000 of them) costs no allocation, so no memory
// grows with what a plugin sends.
TEST(HapticThreadHygiene, TheTrackerSampleFilterNeverAllocatesWhateverSensorsArrive) {
  OtherRigSensorList others;  // two other rigs' sensors, 100 000 to 100 003
  others.rigs[0] = OtherRigSensors{100000, 100001};
  others.rigs[1] = OtherRigSensors{100002, 100003};
  others.count = 2;
  TrackerSampleFilter filter(
      {.base_sensor_id = 0, .head_sensor_id = 1, .other_rigs = others, .tracking_range_m = 50.0});
  std::vector<TrackerSample> samples(10000);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i].sensor_id = static_cast<std::uint32_t>(i % 3 == 0 ? i % 2 : i + 2);  // base, head, strangers
    samples[i].sequence = i + 1;
    samples[i].timestamp_s = 0.001 * static_cast<double>(i);
  }
  std::size_t accepted = 0, unknown = 0;
  ThreadCalls calls;
  std::thread io([&] {
    realtime::name_current_thread(realtime::kIoThreadName);
    test::start_thread_watch(realtime::kIoThreadName);
    for (const TrackerSample& s : samples) {
      const TrackerSampleVerdict v = filter.check(s, s.timestamp_s);
      accepted += v == TrackerSampleVerdict::Accepted ? 1 : 0;
      unknown += v == TrackerSampleVerdict::UnknownSensor ? 1 : 0;
    }
    calls = test::stop_thread_watch();
  });
  io.join();
  EXPECT_EQ(calls.allocations, 0) << "first from " << calls.first_caller;
  EXPECT_EQ(accepted, 3334u);  // every third sample, base or head, each newer than the last
  EXPECT_EQ(unknown, 6666u);
}

/// The server on simulated hardware for 2.5 s, with the calls made on the thread named
/// `thread_name` between 0.5 s and 2.2 s counted. The rig (rig 2) also shares two crates
/// on a floor away from the user: crate 1, which fault_link's rig 1 holds (a replica,
/// moving as its states say), and crate 2, which this rig holds (its state sent every
/// tick).
ThreadCalls run_server_watching(const char* thread_name, ServerReport& r) {
  const fs::path dir = fs::temp_directory_path() / ("mhd_hygiene_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "scene.xml";
  std::ofstream(file) << fmt::format(R"(<?xml version="1.0"?>
<scene version="1" unit="m">
  <include file="{0}/scenes/rigs/pomhi.xml"/>
  <object name="box">
    <material stiffness_N_per_m="800" damping_Ns_per_m="1" static_friction="0.3" dynamic_friction="0.2"/>
    <box size="0.4 0.4 0.4"/>
    <pose position="0 0.8 0.226"/>
  </object>
  <object name="floor">
    <material stiffness_N_per_m="800"/>
    <box size="2 0.1 2"/>
    <pose position="4 -0.05 0"/>
  </object>
  <object name="crate1">
    <material stiffness_N_per_m="800"/>
    <box size="0.2 0.2 0.2"/>
    <pose position="4 0.1 -0.5"/>
    <dynamics mass_kg="1"/>
  </object>
  <object name="crate2">
    <material stiffness_N_per_m="800"/>
    <box size="0.2 0.2 0.2"/>
    <pose position="4 0.1 0.5"/>
    <dynamics mass_kg="1"/>
  </object>
  <sharing rig_id="2">
    <shared_object object="crate1" id="1" rigs="1 2"/>
    <shared_object object="crate2" id="2" rigs="2 1"/>
  </sharing>
  <plugins>
    <plugin kind="device" name="sim_phantom">
      <param name="command_log" value="{1}/device.csv"/>
      <param name="hand_model" value="impedance"/>
    </plugin>
    <plugin kind="tracker" name="sim_is900"/>
    <plugin kind="base" name="sim_omni3">
      <param name="x_m" value="-0.3"/>
      <param name="command_log" value="{1}/base.csv"/>
    </plugin>
    <plugin kind="display" name="null_display"/>
    <plugin kind="link" name="fault_link">
      <param name="start_m" value="4 0.1 -0.5"/>
      <param name="velocity_mps" value="0.1 0 0"/>
    </plugin>
  </plugins>
  <planner kind="predictive"/>
  <simulated_user>
    <param name="path" value="0 0.70 0.3; 1.2 0.70 0.3"/>
    <param name="loop_path" value="true"/>
    <param name="hand_height_m" value="1.02"/>
    <param name="hand_reach_m" value="0.45"/>
    <param name="hand_motion_amplitude_m" value="0.03"/>
  </simulated_user>
</scene>
)", MHD_SOURCE_DIR, dir.string());
  auto read = read_scene_file(file);
  for (const auto& d : read.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!read.ok()) return {};
  auto compiled = compile_scene(*read);
  for (const auto& d : compiled.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!compiled.ok()) return {};
  ServerOptions o;
  o.duration_s = 2.5;
  o.plugin_path = {MHD_FAULT_PLUGIN_DIR};  // fault_link
  o.recording = dir / "run.csv";
  auto build = HapticServer::open(*read, *compiled.value(), o);
  for (const auto& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  if (!build.ok()) return {};
  const ThreadCalls c = count_while(thread_name, 0.5, 2.2, [&] { r = build->server->run(); });
  fs::remove_all(dir);
  return c;
}

TEST(HapticThreadHygiene, TheServerOnSimulatedHardwareNeverLocksAllocatesOrWritesOnTheHapticThread) {
  ServerReport r;
  const ThreadCalls c = run_server_watching(realtime::kHapticThreadName, r);
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_GT(r.status.ticks, 1000u);      // the haptic thread ran while counting
  EXPECT_GT(r.contact_ticks, 0u);        // and rendered contact
  EXPECT_GT(r.base_commands, 0u);        // with the base and the planner at work
  EXPECT_GT(r.sharing.states_obeyed, 1000u);  // and a replica following its link
  EXPECT_GT(r.sharing.states_sent, 1000u);    // and a held crate's state going out
  EXPECT_EQ(c.locks, 0) << "first from " << c.first_caller;
  EXPECT_EQ(c.allocations, 0) << "first from " << c.first_caller;
  EXPECT_EQ(c.writes, 0);
  std::cout << "haptic thread over 1.7 s: " << c.locks << " locks, " << c.allocations << " allocations, " << c.writes
            << " writes; " << r.status.ticks << " ticks, " << r.contact_ticks << " in contact\n";
}

// The io thread's own code: what it does outside its calls into the tracker and the
// base. Those plugins' own locks are theirs (sim_omni3 shares the simulated world under a
// mutex) and are seen here too, which shows the watch was on the io thread.
TEST(HapticThreadHygiene, TheIoThreadNeverLocksOrAllocatesOutsideItsPluginCalls) {
  ServerReport r;
  const ThreadCalls c = run_server_watching(realtime::kIoThreadName, r);
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_GT(r.status.tracker_samples, 100u);  // the io thread took the tracker's samples
  EXPECT_GT(r.base_commands, 0u);             // and sent the base its commands
  EXPECT_GT(c.locks_in_plugins, 0);           // the watch saw the io thread's calls
  EXPECT_EQ(c.locks - c.locks_in_plugins, 0) << "first from " << c.first_caller;
  EXPECT_EQ(c.allocations - c.allocations_in_plugins, 0) << "first from " << c.first_caller;
  std::cout << "io thread over 1.7 s, outside plugin calls: " << c.locks - c.locks_in_plugins << " locks, "
            << c.allocations - c.allocations_in_plugins << " allocations; inside them " << c.locks_in_plugins
            << " locks, " << c.allocations_in_plugins << " allocations; " << r.status.tracker_samples
            << " tracker samples, " << r.base_commands << " base commands\n";
}

}  // namespace
