// No mutex, allocation or I/O on the haptic thread, in the whole
// server on simulated hardware: sim_phantom, sim_is900 and sim_omni3 logging their
// commands, the predictive planner following a simulated user, a recording and a display.
//
// haptic_thread_watch.cpp interposes pthread_mutex_lock, operator new, write and fwrite
// for this binary, counting the calls made on the haptic thread: a mutex, an allocation
// or a write that appears there, in the engine or in a plugin, fails the test. The first test is the
// control: the counters see a thread of that name lock, allocate and write.
// Not run under the sanitizers (they replace these functions themselves).

#include "haptic_thread_watch.h"

#include "haptic_server/haptic_server.h"
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

using test::HapticThreadCalls;

/// What the haptic thread did between from_s and to_s after the call, while `body` runs.
template <class Body>
HapticThreadCalls count_while(double from_s, double to_s, Body&& body) {
  HapticThreadCalls calls;
  std::thread window([&] {
    std::this_thread::sleep_for(std::chrono::duration<double>(from_s));
    test::start_haptic_thread_watch();
    std::this_thread::sleep_for(std::chrono::duration<double>(to_s - from_s));
    calls = test::stop_haptic_thread_watch();
  });
  body();
  window.join();
  return calls;
}

TEST(HapticThreadHygiene, TheCountersSeeAThreadOfThatNameLockAllocateAndWrite) {
  const HapticThreadCalls c = count_while(0.0, 0.3, [] {
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

TEST(HapticThreadHygiene, TheServerOnSimulatedHardwareNeverLocksAllocatesOrWritesOnTheHapticThread) {
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
  ASSERT_TRUE(read.ok());
  auto compiled = compile_scene(*read);
  for (const auto& d : compiled.diagnostics()) ADD_FAILURE() << d.to_string();
  ASSERT_TRUE(compiled.ok());
  ServerOptions o;
  o.duration_s = 2.5;
  o.recording = dir / "run.csv";
  auto build = HapticServer::open(*read, *compiled.value(), o);
  for (const auto& d : build.diagnostics()) ADD_FAILURE() << d.to_string();
  ASSERT_TRUE(build.ok());
  ServerReport r;
  const HapticThreadCalls c = count_while(0.5, 2.2, [&] { r = build->server->run(); });
  EXPECT_FALSE(r.error) << *r.error;
  EXPECT_GT(r.status.ticks, 1000u);      // the haptic thread ran while counting
  EXPECT_GT(r.contact_ticks, 0u);        // and rendered contact
  EXPECT_GT(r.base_commands, 0u);        // with the base and the planner at work
  EXPECT_EQ(c.locks, 0) << "first from " << c.first_caller;
  EXPECT_EQ(c.allocations, 0) << "first from " << c.first_caller;
  EXPECT_EQ(c.writes, 0);
  std::cout << "haptic thread over 1.7 s: " << c.locks << " locks, " << c.allocations << " allocations, " << c.writes
            << " writes; " << r.status.ticks << " ticks, " << r.contact_ticks << " in contact\n";
  fs::remove_all(dir);
}

}  // namespace
