// mhd::sdk::plugin_table in process: the C table a class yields and the rules every call
// keeps (exceptions, lifecycle, overlap, NULL entries, parameters checked at open).
#include <mhd/plugin_sdk.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// A device whose device_read asks the host clock, so a test clock can call back into
/// the plugin while a call is under way.
class Probe {
 public:
  static constexpr std::array kParams{
      mhd::sdk::number("gain", "", "1", "scales the reported x", mhd::sdk::positive()),
      mhd::sdk::choice("mode", "ok|throw|throw_in_open", "ok", "how the probe misbehaves"),
  };
  Probe(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host), gain_(params.number("gain")), mode_(params.text("mode")) {
    if (mode_ == "throw_in_open") throw std::runtime_error("no device on /dev/probe0");
  }
  void start() { ++starts; }
  void stop() { ++stops; }
  void device_info(mhd_device_info& out) { out.max_force_N = 3.0; }
  mhd_status device_read(mhd_device_state& out) {
    if (mode_ == "throw") throw std::runtime_error("encoder cable unplugged");
    out.timestamp_s = mhd::sdk::host_now(host_);
    out.p_D_tool_m[0] = gain_;
    return MHD_OK;
  }
  void device_write(const mhd_device_command& command) { force_x_N = command.force_D_N[0]; }

  int starts = 0;
  int stops = 0;
  double force_x_N = 0.0;

 private:
  mhd_host host_;
  double gain_;
  std::string mode_;
};

class Display {
 public:
  explicit Display(const mhd::sdk::Params&) {}
  void display_write(const mhd_display_frame&) {}
};

constexpr mhd::sdk::PluginInfo kProbeInfo{
    .kind = MHD_KIND_DEVICE, .name = "probe", .version = "1.0.0", .description = "test probe"};
constexpr mhd::sdk::PluginInfo kDisplayInfo{
    .kind = MHD_KIND_DISPLAY, .name = "display", .version = "1.0.0", .description = "test display"};
constexpr mhd_plugin_api kProbe = mhd::sdk::plugin_table<Probe, kProbeInfo>();
constexpr mhd_plugin_api kDisplay = mhd::sdk::plugin_table<Display, kDisplayInfo>();

/// The host clock; when `reenter` is set it calls device_info on it first (a call that
/// overlaps the one asking the time) and keeps that call's outcome.
struct Clock {
  mhd_plugin_instance* reenter = nullptr;
  mhd_status reentered_status = MHD_OK;
  std::string reentered_error;
};

double clock_now(void* context) {
  auto& clock = *static_cast<Clock*>(context);
  if (clock.reenter != nullptr) {
    mhd_device_info info{};
    mhd_error err{};
    clock.reentered_status = kProbe.device_info(clock.reenter, &info, &err);
    clock.reentered_error = err.message;
  }
  return 2.5;
}

class PluginTableTest : public ::testing::Test {
 protected:
  mhd_plugin_instance* open(std::vector<mhd_param> params = {}) {
    err_ = {};
    instance_ = kProbe.open(&host_, params.data(), params.size(), &err_);
    return instance_;
  }
  ~PluginTableTest() override {
    if (instance_ != nullptr) kProbe.close(instance_);
  }

  Clock clock_;
  mhd_host host_{MHD_PLUGIN_ABI_VERSION, sizeof(mhd_host), clock_now, &clock_, nullptr};
  mhd_plugin_instance* instance_ = nullptr;
  mhd_error err_{};
};

TEST_F(PluginTableTest, TheTableCarriesTheInfoAndTheDeclarations) {
  EXPECT_EQ(kProbe.abi_version, MHD_PLUGIN_ABI_VERSION);
  EXPECT_EQ(kProbe.struct_size, sizeof(mhd_plugin_api));
  EXPECT_EQ(kProbe.kind, MHD_KIND_DEVICE);
  EXPECT_STREQ(kProbe.name, "probe");
  EXPECT_EQ(kProbe.param_count, 2u);
  EXPECT_STREQ(kProbe.params[1].name, "mode");
  EXPECT_NE(kProbe.device_read, nullptr);
  EXPECT_EQ(kProbe.tracker_read, nullptr);
  EXPECT_EQ(kProbe.simulate_until, nullptr);  // Probe has none
}

TEST_F(PluginTableTest, AClassWithoutDeviceCallsYieldsNullEntries) {
  EXPECT_EQ(kDisplay.device_info, nullptr);
  EXPECT_EQ(kDisplay.device_read, nullptr);
  EXPECT_EQ(kDisplay.device_write, nullptr);
  EXPECT_EQ(kDisplay.tracker_read, nullptr);
  EXPECT_EQ(kDisplay.tracker_wait, nullptr);
  EXPECT_EQ(kDisplay.base_read, nullptr);
  EXPECT_EQ(kDisplay.base_write, nullptr);
  EXPECT_EQ(kDisplay.counters, nullptr);
  EXPECT_NE(kDisplay.display_write, nullptr);
  EXPECT_EQ(kDisplay.params, nullptr);
  EXPECT_EQ(kDisplay.param_count, 0u);
}

TEST_F(PluginTableTest, AnExceptionInACallBecomesAnErrorWithItsMessage) {
  ASSERT_NE(open({{"mode", "throw"}}), nullptr);
  ASSERT_EQ(kProbe.start(instance_, &err_), MHD_OK);
  mhd_device_state state{};
  EXPECT_EQ(kProbe.device_read(instance_, &state, &err_), MHD_ERROR);
  EXPECT_STREQ(err_.message, "encoder cable unplugged");
}

TEST_F(PluginTableTest, AnExceptionInTheConstructorIsAFailedOpenWithItsMessage) {
  EXPECT_EQ(open({{"mode", "throw_in_open"}}), nullptr);
  EXPECT_STREQ(err_.message, "no device on /dev/probe0");
}

TEST_F(PluginTableTest, CallsBeforeStartAndAfterStopAreRefused) {
  ASSERT_NE(open(), nullptr);
  mhd_device_state state{};
  const mhd_device_command command{0.0, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  EXPECT_EQ(kProbe.device_read(instance_, &state, &err_), MHD_ERROR);
  EXPECT_STREQ(err_.message, "probe is not started");
  EXPECT_EQ(kProbe.device_write(instance_, &command, &err_), MHD_ERROR);
  EXPECT_STREQ(err_.message, "probe is not started");
  mhd_device_info info{};
  EXPECT_EQ(kProbe.device_info(instance_, &info, &err_), MHD_OK);  // allowed while open
  EXPECT_EQ(info.max_force_N, 3.0);
  ASSERT_EQ(kProbe.start(instance_, &err_), MHD_OK);
  EXPECT_EQ(kProbe.device_read(instance_, &state, &err_), MHD_OK);
  EXPECT_EQ(state.timestamp_s, 2.5);
  ASSERT_EQ(kProbe.stop(instance_, &err_), MHD_OK);
  EXPECT_EQ(kProbe.device_read(instance_, &state, &err_), MHD_ERROR);
  EXPECT_STREQ(err_.message, "probe is not started");
}

TEST_F(PluginTableTest, StopReachesTheClassOnlyWhenStarted) {
  ASSERT_NE(open(), nullptr);
  const Probe& probe = reinterpret_cast<const mhd::sdk::detail::Instance<Probe>*>(instance_)->plugin;
  EXPECT_EQ(kProbe.stop(instance_, &err_), MHD_OK);
  EXPECT_EQ(probe.stops, 0);
  ASSERT_EQ(kProbe.start(instance_, &err_), MHD_OK);
  EXPECT_EQ(kProbe.stop(instance_, &err_), MHD_OK);
  EXPECT_EQ(kProbe.stop(instance_, &err_), MHD_OK);
  EXPECT_EQ(probe.starts, 1);
  EXPECT_EQ(probe.stops, 1);
}

TEST_F(PluginTableTest, AnOverlappingCallIsRefusedAndTheFirstGoesOn) {
  ASSERT_NE(open(), nullptr);
  ASSERT_EQ(kProbe.start(instance_, &err_), MHD_OK);
  clock_.reenter = instance_;
  mhd_device_state state{};
  EXPECT_EQ(kProbe.device_read(instance_, &state, &err_), MHD_OK);
  EXPECT_EQ(clock_.reentered_status, MHD_ERROR);
  EXPECT_EQ(clock_.reentered_error, "probe: called while another call is under way");
  clock_.reenter = nullptr;
  mhd_device_info info{};
  EXPECT_EQ(kProbe.device_info(instance_, &info, &err_), MHD_OK);  // the guard is released
}

TEST_F(PluginTableTest, NullArgumentsAreRefusedBeforeTheClass) {
  ASSERT_NE(open(), nullptr);
  ASSERT_EQ(kProbe.start(instance_, &err_), MHD_OK);
  EXPECT_EQ(kProbe.device_read(instance_, nullptr, &err_), MHD_ERROR);
  EXPECT_STREQ(err_.message, "device_read: out is NULL");
  EXPECT_EQ(kProbe.device_write(instance_, nullptr, &err_), MHD_ERROR);
  EXPECT_STREQ(err_.message, "device_write: command is NULL");
  EXPECT_EQ(kProbe.start(nullptr, &err_), MHD_ERROR);
  EXPECT_STREQ(err_.message, "instance is NULL");
}

TEST_F(PluginTableTest, TheHostTableIsChecked) {
  mhd_error err{};
  EXPECT_EQ(kProbe.open(nullptr, nullptr, 0, &err), nullptr);
  EXPECT_STREQ(err.message, "the host table is NULL");
  mhd_host old = host_;
  old.abi_version = MHD_PLUGIN_ABI_VERSION - 1;  // a host of the ABI before this one
  EXPECT_EQ(kProbe.open(&old, nullptr, 0, &err), nullptr);
  EXPECT_EQ(std::string(err.message), "host ABI version " + std::to_string(MHD_PLUGIN_ABI_VERSION - 1) + " is not " +
                                          std::to_string(MHD_PLUGIN_ABI_VERSION));
  mhd_host no_clock = host_;
  no_clock.now_s = nullptr;
  EXPECT_EQ(kProbe.open(&no_clock, nullptr, 0, &err), nullptr);
  EXPECT_STREQ(err.message, "the host gives no clock (now_s is NULL)");
}

TEST_F(PluginTableTest, ABadParameterIsRefusedAtOpenNamingIt) {
  EXPECT_EQ(open({{"gain", "-1"}}), nullptr);
  EXPECT_STREQ(err_.message, "parameter 'gain' must be a number > 0, got '-1'");
  EXPECT_EQ(open({{"mode", "fast"}}), nullptr);
  EXPECT_STREQ(err_.message, "parameter 'mode' must be one of ok|throw|throw_in_open, got 'fast'");
  EXPECT_EQ(open({{"colour", "red"}}), nullptr);
  EXPECT_STREQ(err_.message, "unknown parameter 'colour' (known: gain, mode)");
}

TEST_F(PluginTableTest, AGoodParameterSetIsNeverRefusedAndReachesTheClass) {
  for (const char* gain : {"1e-9", "0.5", " 2 ", "1e300"}) {
    ASSERT_NE(open({{"gain", gain}, {"mode", "ok"}}), nullptr) << gain << ": " << err_.message;
    ASSERT_EQ(kProbe.start(instance_, &err_), MHD_OK);
    mhd_device_state state{};
    ASSERT_EQ(kProbe.device_read(instance_, &state, &err_), MHD_OK);
    EXPECT_EQ(state.p_D_tool_m[0], std::stod(gain));
    kProbe.close(instance_);
    instance_ = nullptr;
  }
  ASSERT_NE(open(), nullptr) << err_.message;  // every default is valid too
}

TEST_F(PluginTableTest, TheEntryServesOnlyItsOwnAbi) {
  EXPECT_EQ(mhd::sdk::entry(kProbe, MHD_PLUGIN_ABI_VERSION), &kProbe);
  EXPECT_EQ(mhd::sdk::entry(kProbe, 2), nullptr);
}

}  // namespace

namespace {

/// A tracker whose tracker_read reports its own status (the form for a tracker that can
/// fail or be deactivated), and one whose tracker_read returns a count only.
class StatusTracker {
 public:
  static constexpr std::array kParams{
      mhd::sdk::choice("mode", "ok|empty|deactivate", "ok", "what tracker_read reports"),
  };
  explicit StatusTracker(const mhd::sdk::Params& params) : mode_(params.text("mode")) {}
  mhd_status tracker_read(std::span<mhd_tracker_sample> out, std::size_t& count) {
    if (mode_ == "deactivate") return MHD_DEACTIVATE;
    if (mode_ == "empty" || out.empty()) return MHD_NO_DATA;
    out[0] = {};
    out[0].sequence = 7;
    count = 1;
    return MHD_OK;
  }

 private:
  std::string mode_;
};

constexpr mhd::sdk::PluginInfo kStatusTrackerInfo{
    .kind = MHD_KIND_TRACKER, .name = "status_tracker", .version = "1.0.0", .description = "test tracker"};
constexpr mhd_plugin_api kStatusTracker = mhd::sdk::plugin_table<StatusTracker, kStatusTrackerInfo>();

double fixed_now(void*) { return 1.0; }

struct TrackerRead {
  mhd_status status;
  std::size_t count;
  std::uint64_t first_sequence;
};

TrackerRead read_status_tracker(const char* mode) {
  const mhd_host host{MHD_PLUGIN_ABI_VERSION, sizeof(mhd_host), fixed_now, nullptr, nullptr};
  const mhd_param params[] = {{"mode", mode}};
  mhd_error err{};
  mhd_plugin_instance* t = kStatusTracker.open(&host, params, 1, &err);
  EXPECT_NE(t, nullptr) << err.message;
  if (t == nullptr) return {MHD_ERROR, 0, 0};
  EXPECT_EQ(kStatusTracker.start(t, &err), MHD_OK);
  std::array<mhd_tracker_sample, 4> out{};
  std::size_t count = 99;
  const mhd_status s = kStatusTracker.tracker_read(t, out.data(), out.size(), &count, &err);
  kStatusTracker.close(t);
  return {s, count, out[0].sequence};
}

TEST(PluginTableTracker, ATrackerReadWithAStatusPassesItsStatusAndCount) {
  ASSERT_NE(kStatusTracker.tracker_read, nullptr);
  const TrackerRead ok = read_status_tracker("ok");
  EXPECT_EQ(ok.status, MHD_OK);
  EXPECT_EQ(ok.count, 1u);
  EXPECT_EQ(ok.first_sequence, 7u);
  const TrackerRead deactivated = read_status_tracker("deactivate");
  EXPECT_EQ(deactivated.status, MHD_DEACTIVATE);
  EXPECT_EQ(deactivated.count, 0u);  // the count starts at 0 whatever the host left there
  const TrackerRead empty = read_status_tracker("empty");
  EXPECT_EQ(empty.status, MHD_NO_DATA);
  EXPECT_EQ(empty.count, 0u);
}

}  // namespace
