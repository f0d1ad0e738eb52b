// Driving one plugin: lifecycle order, kind-specific calls, what the host checks in
// what plugins return and in what it sends them. All through real test plugins.

#include "plugin_host/host_services.h"
#include "plugin_host/plugin_instance.h"
#include "test_plugins.h"

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <array>
#include <limits>
#include <map>
#include <memory>
#include <string>

namespace mhd {
namespace {

using Params = std::map<std::string, std::string>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::shared_ptr<const PluginLibrary> load(const std::filesystem::path& path) {
  auto loaded = PluginLibrary::load(path);
  if (!loaded.ok()) ADD_FAILURE() << loaded.error().to_string();
  return loaded.ok() ? loaded.value() : nullptr;
}

std::shared_ptr<const PluginLibrary> load_test(const std::string& name) { return load(test::test_plugin(name)); }

/// good_device's log of the lifecycle calls that reached it (exported for tests only).
class CallLog {
 public:
  explicit CallLog(const PluginLibrary& library) {
    handle_ = dlopen(std::filesystem::absolute(library.path()).c_str(), RTLD_NOW | RTLD_NOLOAD);
    EXPECT_NE(handle_, nullptr);
    get_ = reinterpret_cast<const char* (*)()>(dlsym(handle_, "mhd_test_call_log"));
    reinterpret_cast<void (*)()>(dlsym(handle_, "mhd_test_clear_call_log"))();
  }
  ~CallLog() { dlclose(handle_); }
  CallLog(const CallLog&) = delete;
  CallLog& operator=(const CallLog&) = delete;
  [[nodiscard]] std::string calls() const { return get_(); }

 private:
  void* handle_ = nullptr;
  const char* (*get_)() = nullptr;
};

void expect_error(const PluginError& e, PluginErrorKind kind, const std::string& text) {
  EXPECT_EQ(e.kind, kind) << to_string(e.kind);
  EXPECT_EQ(e.to_string(), text);
}

class PluginInstanceTest : public ::testing::Test {
 protected:
  /// An instance of test plugin `name`, opened with `params` and started.
  PluginInstance running(const std::string& name, const Params& params = {}) {
    PluginInstance instance(load_test(name));
    EXPECT_TRUE(instance.open(params, host_.abi()).ok());
    EXPECT_TRUE(instance.start().ok());
    return instance;
  }

  HostServices host_;
};

TEST_F(PluginInstanceTest, LifecycleInOrder) {
  PluginInstance device(load_test("good_device"));
  CallLog log(*device.library());
  EXPECT_EQ(device.state(), PluginState::Loaded);
  EXPECT_EQ(device.name(), "good_device");
  EXPECT_EQ(device.kind(), PluginKind::Device);
  ASSERT_TRUE(device.open({}, host_.abi()).ok());
  EXPECT_EQ(device.state(), PluginState::Open);
  ASSERT_TRUE(device.start().ok());
  EXPECT_EQ(device.state(), PluginState::Running);
  ASSERT_TRUE(device.stop().ok());
  EXPECT_EQ(device.state(), PluginState::Stopped);
  ASSERT_TRUE(device.start().ok());  // stopped -> running again
  EXPECT_EQ(device.state(), PluginState::Running);
  EXPECT_TRUE(device.close().ok());  // stops first
  EXPECT_EQ(device.state(), PluginState::Closed);
  EXPECT_TRUE(device.close().ok());  // closing twice does nothing
  EXPECT_EQ(log.calls(), "open start stop start stop close ");
}

TEST_F(PluginInstanceTest, DestructorStopsAndCloses) {
  auto library = load_test("good_device");
  CallLog log(*library);
  {
    PluginInstance device(library);
    ASSERT_TRUE(device.open({}, host_.abi()).ok());
    ASSERT_TRUE(device.start().ok());
  }
  EXPECT_EQ(log.calls(), "open start stop close ");
}

TEST_F(PluginInstanceTest, MovedInstanceClosesOnce) {
  auto library = load_test("good_device");
  CallLog log(*library);
  {
    PluginInstance first(library);
    ASSERT_TRUE(first.open({}, host_.abi()).ok());
    PluginInstance second(std::move(first));
    EXPECT_EQ(second.state(), PluginState::Open);
    EXPECT_EQ(first.state(), PluginState::Closed);  // a moved-from instance is closed
    expect_error(first.start().error(), PluginErrorKind::WrongState,
                 "plugin '': start called while the plugin is closed; it must be open or stopped");
  }
  EXPECT_EQ(log.calls(), "open close ");
}

TEST_F(PluginInstanceTest, CallsOutOfOrderAreRefusedBeforeThePluginSeesThem) {
  PluginInstance device(load_test("good_device"));
  CallLog log(*device.library());
  DeviceState state{};
  expect_error(device.start().error(), PluginErrorKind::WrongState,
               "plugin 'good_device': start called while the plugin is loaded; it must be open or stopped");
  expect_error(device.device_read(state).error(), PluginErrorKind::WrongState,
               "plugin 'good_device': device_read called while the plugin is loaded; it must be running");
  expect_error(device.device_info().error(), PluginErrorKind::WrongState,
               "plugin 'good_device': device_info called while the plugin is loaded; it must be open, running or "
               "stopped");
  ASSERT_TRUE(device.open({}, host_.abi()).ok());
  expect_error(device.open({}, host_.abi()).error(), PluginErrorKind::WrongState,
               "plugin 'good_device': open called while the plugin is open; it must be loaded");
  expect_error(device.stop().error(), PluginErrorKind::WrongState,
               "plugin 'good_device': stop called while the plugin is open; it must be running");
  expect_error(device.device_write(DeviceCommand{}).error(), PluginErrorKind::WrongState,
               "plugin 'good_device': device_write called while the plugin is open; it must be running");
  ASSERT_TRUE(device.start().ok());
  expect_error(device.start().error(), PluginErrorKind::WrongState,
               "plugin 'good_device': start called while the plugin is running; it must be open or stopped");
  ASSERT_TRUE(device.stop().ok());
  expect_error(device.stop().error(), PluginErrorKind::WrongState,
               "plugin 'good_device': stop called while the plugin is stopped; it must be running");
  EXPECT_TRUE(device.close().ok());
  expect_error(device.start().error(), PluginErrorKind::WrongState,
               "plugin 'good_device': start called while the plugin is closed; it must be open or stopped");
  expect_error(device.open({}, host_.abi()).error(), PluginErrorKind::WrongState,
               "plugin 'good_device': open called while the plugin is closed; it must be loaded");
  EXPECT_EQ(log.calls(), "open start stop close ");
}

TEST_F(PluginInstanceTest, CallsOfAnotherKindAreRefused) {
  PluginInstance device = running("good_device");
  std::array<TrackerSample, 4> samples{};
  std::size_t count = 99;
  expect_error(device.tracker_read(samples, count).error(), PluginErrorKind::WrongKind,
               "plugin 'good_device': tracker_read called on a device plugin");
  EXPECT_EQ(count, 0u);
  BaseState base{};
  expect_error(device.base_read(base).error(), PluginErrorKind::WrongKind,
               "plugin 'good_device': base_read called on a device plugin");
  expect_error(device.display_write(DisplayFrame{}).error(), PluginErrorKind::WrongKind,
               "plugin 'good_device': display_write called on a device plugin");
}

TEST_F(PluginInstanceTest, DeviceReadsFixedDataWithParamsAndTheHostClock) {
  PluginInstance device = running("good_device", {{"tool_x_m", "0.075"}});
  const double before_s = host_.now_s();
  DeviceState state{};
  auto read = device.device_read(state);
  ASSERT_TRUE(read.ok()) << read.error().to_string();
  EXPECT_EQ(read.value(), PluginCallStatus::Ok);
  EXPECT_EQ(state.p_D_tool_m[0], 0.075);
  EXPECT_EQ(state.p_D_tool_m[1], 0.02);
  EXPECT_EQ(state.p_D_tool_m[2], -0.02);
  EXPECT_EQ(state.q_D_tool_wxyz[0], 1.0);
  EXPECT_GE(state.timestamp_s, before_s);
  EXPECT_LE(state.timestamp_s, host_.now_s());
  EXPECT_EQ(state.buttons, 1u);
}

TEST_F(PluginInstanceTest, DeviceInfoIsReadAtOpen) {
  PluginInstance device(load_test("good_device"));
  ASSERT_TRUE(device.open({{"max_force_N", "3.25"}}, host_.abi()).ok());
  auto info = device.device_info();
  ASSERT_TRUE(info.ok());
  EXPECT_EQ(info.value().max_force_N, 3.25);
  EXPECT_EQ(info.value().dof_in, 3u);
  EXPECT_EQ(info.value().workspace_box_count, 1u);
  EXPECT_EQ(info.value().workspace[0].max_m[2], 0.1);
}

TEST_F(PluginInstanceTest, BadDeviceInfoFailsTheOpen) {
  PluginInstance device(load_test("good_device"));
  CallLog log(*device.library());
  expect_error(device.open({{"max_force_N", "0"}}, host_.abi()).error(), PluginErrorKind::InvalidData,
               "plugin 'good_device': device_info returned max_force_N = 0, which must be > 0");
  EXPECT_EQ(device.state(), PluginState::Loaded);
  expect_error(device.open({{"max_force_N", "-1e300"}}, host_.abi()).error(), PluginErrorKind::InvalidData,
               "plugin 'good_device': device_info returned max_force_N = -1e+300, which must be > 0");
  EXPECT_EQ(log.calls(), "open close open close ");
}

TEST_F(PluginInstanceTest, UndeclaredOrBadParametersAreRefusedBeforeOpen) {
  PluginInstance device(load_test("good_device"));
  CallLog log(*device.library());
  expect_error(device.open({{"max_torque_Nm", "0.5"}}, host_.abi()).error(), PluginErrorKind::BadParameter,
               "plugin 'good_device': unknown parameter 'max_torque_Nm' (known: tool_x_m, max_force_N, read_status, "
               "fail)");
  expect_error(device.open({{"read_status", "sometimes"}, {"tool_x_m", "x"}}, host_.abi()).error(),
               PluginErrorKind::BadParameter,
               "plugin 'good_device': parameter 'read_status' must be one of ok|no_data|deactivate|error|bogus, got "
               "'sometimes'; parameter 'tool_x_m' must be a number (m), got 'x'");
  EXPECT_EQ(log.calls(), "");  // open() never saw them
  // The dual: declared parameters with good values reach open().
  ASSERT_TRUE(device.open({{"read_status", "ok"}, {"tool_x_m", " 0.01 "}}, host_.abi()).ok());
  EXPECT_EQ(log.calls(), "open ");
}

TEST_F(PluginInstanceTest, ForceIsScaledToTheDeviceLimitKeepingItsDirection) {
  PluginInstance device = running("good_device", {{"max_force_N", "5"}});
  DeviceCommand command{};
  command.force_D_N[0] = 6.0;
  command.force_D_N[1] = -8.0;  // |F| = 10 N: halved
  command.torque_D_Nm[2] = 1.0;  // a 3-DOF-out device gets no torque
  ASSERT_TRUE(device.device_write(command).ok());
  DeviceState state{};
  ASSERT_TRUE(device.device_read(state).ok());
  EXPECT_DOUBLE_EQ(state.v_D_tool_mps[0], 3.0);  // good_device echoes the force it got
  EXPECT_DOUBLE_EQ(state.v_D_tool_mps[1], -4.0);
  EXPECT_EQ(state.v_D_tool_mps[2], 0.0);
  // The dual: a force within the limit passes unchanged.
  command = DeviceCommand{};
  command.force_D_N[2] = 4.5;
  ASSERT_TRUE(device.device_write(command).ok());
  ASSERT_TRUE(device.device_read(state).ok());
  EXPECT_EQ(state.v_D_tool_mps[2], 4.5);
}

TEST_F(PluginInstanceTest, NonFiniteCommandsNeverReachThePlugin) {
  PluginInstance device = running("good_device");
  DeviceCommand command{};
  command.force_D_N[1] = kNaN;
  expect_error(device.device_write(command).error(), PluginErrorKind::InvalidData,
               "plugin 'good_device': refused to send a non-finite force_D_N[1] to device_write");
  command.force_D_N[1] = 0.0;
  command.torque_D_Nm[0] = kNaN;
  expect_error(device.device_write(command).error(), PluginErrorKind::InvalidData,
               "plugin 'good_device': refused to send a non-finite torque_D_Nm[0] to device_write");
  expect_error(device.simulate_until(kNaN).error(), PluginErrorKind::InvalidData,
               "plugin 'good_device': refused to send a non-finite t_s to simulate_until");
  DeviceState state{};
  ASSERT_TRUE(device.device_read(state).ok());
  EXPECT_EQ(state.v_D_tool_mps[1], 0.0);
}

TEST_F(PluginInstanceTest, NonFiniteDeviceStateIsInvalidData) {
  PluginInstance device = running("nan_device");
  DeviceState state{};
  state.p_D_tool_m[0] = 42.0;
  expect_error(device.device_read(state).error(), PluginErrorKind::InvalidData,
               "plugin 'nan_device': device_read returned a non-finite p_D_tool_m[1]");
  EXPECT_EQ(state.p_D_tool_m[0], 42.0);  // untouched
}

TEST_F(PluginInstanceTest, ReadStatuses) {
  DeviceState state{};
  state.p_D_tool_m[0] = 42.0;
  {
    PluginInstance device = running("good_device", {{"read_status", "no_data"}});
    auto read = device.device_read(state);
    ASSERT_TRUE(read.ok());
    EXPECT_EQ(read.value(), PluginCallStatus::NoData);
    EXPECT_EQ(state.p_D_tool_m[0], 42.0);  // untouched
  }
  {
    PluginInstance device = running("good_device", {{"read_status", "deactivate"}});
    auto read = device.device_read(state);
    ASSERT_TRUE(read.ok());
    EXPECT_EQ(read.value(), PluginCallStatus::Deactivate);
    EXPECT_EQ(state.p_D_tool_m[0], 42.0);
  }
  {
    PluginInstance device = running("good_device", {{"read_status", "error"}});
    expect_error(device.device_read(state).error(), PluginErrorKind::CallFailed,
                 "plugin 'good_device': device_read failed: encoder cable unplugged");
  }
  {
    PluginInstance device = running("good_device", {{"read_status", "bogus"}});
    expect_error(device.device_read(state).error(), PluginErrorKind::InvalidData,
                 "plugin 'good_device': device_read returned status 7, which is not an mhd_status");
  }
  EXPECT_EQ(state.p_D_tool_m[0], 42.0);
}

TEST_F(PluginInstanceTest, OpenFailureSaysWhy) {
  PluginInstance device(load_test("open_fails"));
  expect_error(device.open({}, host_.abi()).error(), PluginErrorKind::OpenFailed,
               "plugin 'open_fails': open failed: no device on /dev/ttyUSB0");
  EXPECT_EQ(device.state(), PluginState::Loaded);
}

TEST_F(PluginInstanceTest, UnknownParameterFailsTheOpen) {
  // The plugin declares no parameters: the host refuses any before open() sees it.
  PluginInstance device(load_test("rejects_unknown_param"));
  expect_error(device.open({{"x", "1"}}, host_.abi()).error(), PluginErrorKind::BadParameter,
               "plugin 'rejects_unknown_param': unknown parameter 'x' (known: none)");
  EXPECT_TRUE(device.open({}, host_.abi()).ok());
}

TEST_F(PluginInstanceTest, StartFailureKeepsThePluginOpen) {
  PluginInstance device(load_test("good_device"));
  ASSERT_TRUE(device.open({{"fail", "start"}}, host_.abi()).ok());
  expect_error(device.start().error(), PluginErrorKind::StartFailed,
               "plugin 'good_device': start failed: motors not powered");
  EXPECT_EQ(device.state(), PluginState::Open);
}

TEST_F(PluginInstanceTest, StopFailureStillStops) {
  PluginInstance device = running("good_device", {{"fail", "stop"}});
  expect_error(device.stop().error(), PluginErrorKind::StopFailed,
               "plugin 'good_device': stop failed: brake did not engage");
  EXPECT_EQ(device.state(), PluginState::Stopped);
}

TEST_F(PluginInstanceTest, CloseReportsTheStopFailureOfARunningPlugin) {
  PluginInstance device = running("good_device", {{"fail", "stop"}});
  expect_error(device.close().error(), PluginErrorKind::StopFailed,
               "plugin 'good_device': stop failed: brake did not engage");
  EXPECT_EQ(device.state(), PluginState::Closed);
}

TEST_F(PluginInstanceTest, SimulateUntil) {
  PluginInstance device = running("good_device");
  EXPECT_TRUE(device.simulates());
  auto step = device.simulate_until(0.5);
  ASSERT_TRUE(step.ok());
  EXPECT_EQ(step.value(), PluginCallStatus::Ok);

  PluginInstance display(load(test::null_display_plugin()));
  EXPECT_FALSE(display.simulates());
  ASSERT_TRUE(display.open({}, host_.abi()).ok());
  ASSERT_TRUE(display.start().ok());
  expect_error(display.simulate_until(0.5).error(), PluginErrorKind::WrongKind,
               "plugin 'null_display': simulate_until called on a plugin that does not simulate");
}

TEST_F(PluginInstanceTest, TrackerSamples) {
  PluginInstance tracker = running("good_tracker");
  std::array<TrackerSample, 4> samples{};
  std::size_t count = 0;
  auto read = tracker.tracker_read(samples, count);
  ASSERT_TRUE(read.ok()) << read.error().to_string();
  EXPECT_EQ(read.value(), PluginCallStatus::Ok);
  ASSERT_EQ(count, 2u);
  EXPECT_EQ(samples[1].sensor_id, 1u);
  EXPECT_EQ(samples[1].p_T_m[0], 0.1);
  EXPECT_EQ(samples[1].sequence, 2u);
}

TEST_F(PluginInstanceTest, TrackerNoData) {
  PluginInstance tracker = running("good_tracker", {{"mode", "no_data"}});
  std::array<TrackerSample, 4> samples{};
  std::size_t count = 99;
  auto read = tracker.tracker_read(samples, count);
  ASSERT_TRUE(read.ok());
  EXPECT_EQ(read.value(), PluginCallStatus::NoData);
  EXPECT_EQ(count, 0u);
}

TEST_F(PluginInstanceTest, TrackerWaitSaysWhetherDataIsThere) {
  PluginInstance tracker = running("good_tracker");
  EXPECT_TRUE(tracker.waits());
  auto ready = tracker.tracker_wait(0.01);
  ASSERT_TRUE(ready.ok()) << ready.error().to_string();
  EXPECT_EQ(ready.value(), PluginCallStatus::Ok);
  PluginInstance silent = running("good_tracker", {{"mode", "no_data"}});
  auto timed_out = silent.tracker_wait(0.01);
  ASSERT_TRUE(timed_out.ok());
  EXPECT_EQ(timed_out.value(), PluginCallStatus::NoData);
  expect_error(silent.tracker_wait(std::numeric_limits<double>::quiet_NaN()).error(), PluginErrorKind::InvalidData,
               "plugin 'good_tracker': refused to send a non-finite timeout_s to tracker_wait");
  PluginInstance device = running("good_device");
  EXPECT_FALSE(device.waits());
  expect_error(device.tracker_wait(0.01).error(), PluginErrorKind::WrongKind,
               "plugin 'good_device': tracker_wait called on a plugin that does not wait");
}

TEST_F(PluginInstanceTest, CountersAreReadAndTheirNamesChecked) {
  PluginInstance tracker = running("good_tracker");
  std::array<TrackerSample, 4> samples{};
  std::size_t count = 0;
  ASSERT_TRUE(tracker.tracker_read(samples, count).ok());
  ASSERT_TRUE(tracker.tracker_read(samples, count).ok());
  ASSERT_TRUE(tracker.counts());
  std::array<CounterReading, 4> counters{};
  auto n = tracker.counters(counters);
  ASSERT_TRUE(n.ok()) << n.error().to_string();
  ASSERT_EQ(n.value(), 2u);
  EXPECT_STREQ(counters[0].name, "reads");
  EXPECT_EQ(counters[0].value, 2u);
  EXPECT_STREQ(counters[1].name, "dropped_test");
  EXPECT_EQ(counters[1].value, 7u);
  std::array<CounterReading, 1> one{};
  auto first_only = tracker.counters(one);  // the plugin keeps 2: only the first fits
  ASSERT_TRUE(first_only.ok());
  EXPECT_EQ(first_only.value(), 1u);

  PluginInstance bad = running("good_tracker", {{"mode", "bad_counter"}});
  expect_error(bad.counters(counters).error(), PluginErrorKind::InvalidData,
               "plugin 'good_tracker': counters returned counters[1].name that is missing, empty, too long or not printable");
  PluginInstance device = running("good_device");
  EXPECT_FALSE(device.counts());
  expect_error(device.counters(counters).error(), PluginErrorKind::WrongKind,
               "plugin 'good_device': counters called on a plugin that keeps none");
}

TEST_F(PluginInstanceTest, BadTrackerSamplesAreInvalidData) {
  std::array<TrackerSample, 4> samples{};
  std::size_t count = 99;
  {
    PluginInstance tracker = running("good_tracker", {{"mode", "too_many"}});
    expect_error(tracker.tracker_read(samples, count).error(), PluginErrorKind::InvalidData,
                 "plugin 'good_tracker': tracker_read returned count 5 for capacity 4");
    EXPECT_EQ(count, 0u);
  }
  {
    PluginInstance tracker = running("good_tracker", {{"mode", "bad_quat"}});
    expect_error(tracker.tracker_read(samples, count).error(), PluginErrorKind::InvalidData,
                 "plugin 'good_tracker': tracker_read returned samples[0].q_T_wxyz of norm 2, not a unit quaternion");
  }
  {
    PluginInstance tracker = running("good_tracker", {{"mode", "nan"}});
    expect_error(tracker.tracker_read(samples, count).error(), PluginErrorKind::InvalidData,
                 "plugin 'good_tracker': tracker_read returned a non-finite samples[1].p_T_m[2]");
    EXPECT_EQ(count, 0u);
  }
}

TEST_F(PluginInstanceTest, BaseWriteAndRead) {
  PluginInstance base = running("good_base");
  BaseCommand command{};
  command.vx_mps = 0.25;
  command.omega_radps = -0.5;
  ASSERT_TRUE(base.base_write(command).ok());
  BaseState state{};
  auto read = base.base_read(state);
  ASSERT_TRUE(read.ok()) << read.error().to_string();
  EXPECT_EQ(state.vx_mps, 0.25);
  EXPECT_EQ(state.omega_radps, -0.5);
  command.omega_radps = std::numeric_limits<double>::infinity();
  expect_error(base.base_write(command).error(), PluginErrorKind::InvalidData,
               "plugin 'good_base': refused to send a non-finite omega_radps to base_write");
}

TEST_F(PluginInstanceTest, DisplayFrames) {
  PluginInstance display(load(test::null_display_plugin()));
  ASSERT_TRUE(display.open({}, host_.abi()).ok());
  ASSERT_TRUE(display.start().ok());
  DisplayFrame frame{};
  frame.q_W_head_wxyz[0] = 1.0;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(display.display_write(frame).ok());
  frame.q_W_head_wxyz[3] = kNaN;
  expect_error(display.display_write(frame).error(), PluginErrorKind::InvalidData,
               "plugin 'null_display': refused to send a non-finite q_W_head_wxyz[3] to display_write");
  PluginInstance other(load(test::null_display_plugin()));
  expect_error(other.open({{"colour", "red"}}, host_.abi()).error(), PluginErrorKind::BadParameter,
               "plugin 'null_display': unknown parameter 'colour' (known: verbose)");
}

// A state and a push, as the haptic thread sends them.
std::array<LinkMessage, 2> state_and_push() {
  std::array<LinkMessage, 2> m{};
  m[0].kind = LinkMessageKind::State;
  m[0].object_id = 7;
  m[0].rig_id = 1;
  m[0].term = 2;
  m[0].sequence = 11;
  m[0].timestamp_s = 3.5;
  m[0].p_W_m = {0.1, 0.2, 0.3};
  m[0].v_W_mps = {0.5, 0.0, 0.0};
  m[1].kind = LinkMessageKind::Push;
  m[1].object_id = 7;
  m[1].rig_id = 1;
  m[1].f_W_N = {1.0, -2.0, 3.0};
  m[1].p_O_m = {0.0, 0.0, 0.2};
  return m;
}

TEST_F(PluginInstanceTest, LinkMessagesGoAndComeBackWhole) {
  PluginInstance link = running("good_link");
  EXPECT_EQ(link.kind(), PluginKind::Link);
  const std::array<LinkMessage, 2> sent = state_and_push();
  ASSERT_TRUE(link.link_send(sent).ok());
  std::array<LinkMessage, 4> got{};
  std::size_t count = 0;
  auto read = link.link_read(got, count);
  ASSERT_TRUE(read.ok()) << read.error().to_string();
  ASSERT_EQ(read.value(), PluginCallStatus::Ok);
  ASSERT_EQ(count, 2u);
  EXPECT_EQ(got[0].kind, LinkMessageKind::State);
  EXPECT_EQ(got[0].object_id, 7u);
  EXPECT_EQ(got[0].rig_id, 2u);  // good_link's echo, "from the other rig"
  EXPECT_EQ(got[0].term, 2u);
  EXPECT_EQ(got[0].sequence, 11u);
  EXPECT_EQ(got[0].timestamp_s, 3.5);
  EXPECT_EQ(got[0].p_W_m, sent[0].p_W_m);
  EXPECT_EQ(got[0].v_W_mps, sent[0].v_W_mps);
  EXPECT_EQ(got[1].kind, LinkMessageKind::Push);
  EXPECT_EQ(got[1].f_W_N, sent[1].f_W_N);
  EXPECT_EQ(got[1].p_O_m, sent[1].p_O_m);
  // Nothing more: NoData, count 0.
  read = link.link_read(got, count);
  ASSERT_TRUE(read.ok());
  EXPECT_EQ(read.value(), PluginCallStatus::NoData);
  EXPECT_EQ(count, 0u);
}

TEST_F(PluginInstanceTest, BadLinkMessagesNeverReachThePluginNorTheHost) {
  std::array<LinkMessage, 2> m = state_and_push();
  {
    PluginInstance link = running("good_link");
    m[1].f_W_N[2] = kNaN;
    expect_error(link.link_send(m).error(), PluginErrorKind::InvalidData,
                 "plugin 'good_link': refused to send a non-finite messages[1].f_W_N[2] to link_send");
    m = state_and_push();
    m[0].q_W_wxyz = {0.5, 0.0, 0.0, 0.0};
    expect_error(link.link_send(m).error(), PluginErrorKind::InvalidData,
                 "plugin 'good_link': refused to send messages[0].q_W_wxyz of norm 0.5, not a unit quaternion to "
                 "link_send");
    std::array<LinkMessage, 1> nothing{};
    std::size_t count = 9;
    ASSERT_TRUE(link.link_read(nothing, count).ok());
    EXPECT_EQ(count, 0u);  // neither reached the plugin
  }
  const std::pair<const char*, const char*> modes[] = {
      {"nan", "plugin 'good_link': link_read returned a non-finite messages[0].f_W_N[1]"},
      {"bad_quat", "plugin 'good_link': link_read returned messages[0].q_W_wxyz of norm 2, not a unit quaternion"},
      {"bad_kind", "plugin 'good_link': link_read returned an unknown messages[0].kind 9"},
      {"too_many", "plugin 'good_link': link_read returned count 5 for capacity 4"}};
  for (const auto& [mode, text] : modes) {
    SCOPED_TRACE(mode);
    PluginInstance link = running("good_link", {{"mode", mode}});
    ASSERT_TRUE(link.link_send(state_and_push()).ok());
    std::array<LinkMessage, 4> got{};
    std::size_t count = 99;
    expect_error(link.link_read(got, count).error(), PluginErrorKind::InvalidData, text);
    EXPECT_EQ(count, 0u);
  }
}

TEST_F(PluginInstanceTest, LinkCallsOnAnotherKindAreRefused) {
  PluginInstance tracker = running("good_tracker");
  const std::array<LinkMessage, 2> m = state_and_push();
  EXPECT_EQ(tracker.link_send(m).error().kind, PluginErrorKind::WrongKind);
}

}  // namespace
}  // namespace mhd
