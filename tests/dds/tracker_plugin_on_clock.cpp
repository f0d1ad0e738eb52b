#include "tracker_plugin_on_clock.h"

#include <gtest/gtest.h>

#include <thread>

namespace mhd::dds::test {

double steady_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

TrackerPluginOnClock::TrackerPluginOnClock(const char* plugin_file,
                                           std::initializer_list<std::pair<const char*, const char*>> params)
    : file_(plugin_file), plugin_(file_.api(), clock_now(host_), params) {}

const mhd_host& TrackerPluginOnClock::clock_now(mhd::test::FakeHost& host) {
  host.now_s = steady_s();
  return host.host;
}

std::vector<mhd_tracker_sample> TrackerPluginOnClock::read_for(std::chrono::milliseconds timeout, std::size_t want) {
  std::vector<mhd_tracker_sample> got;
  mhd_tracker_sample buffer[16];
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (got.size() < want && std::chrono::steady_clock::now() < end) {
    host_.now_s = steady_s();
    std::size_t count = 0;
    mhd_error err{};
    const mhd_status status = file_.api().tracker_read(plugin_.get(), buffer, 16, &count, &err);
    EXPECT_TRUE(status == MHD_OK || status == MHD_NO_DATA) << err.message;
    for (std::size_t i = 0; i < count; ++i) {
      EXPECT_LE(buffer[i].timestamp_s, host_.now_s + 0.01);
      EXPECT_GE(buffer[i].timestamp_s, host_.now_s - 0.1);
      got.push_back(buffer[i]);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return got;
}

std::map<std::string, std::uint64_t> TrackerPluginOnClock::counters() {
  mhd_counter out[32];
  std::size_t count = 0;
  mhd_error err{};
  EXPECT_EQ(file_.api().counters(plugin_.get(), out, 32, &count, &err), MHD_OK) << err.message;
  std::map<std::string, std::uint64_t> by_name;
  for (std::size_t i = 0; i < count && i < 32; ++i) by_name[out[i].name] = out[i].value;
  return by_name;
}

}  // namespace mhd::dds::test
