#pragma once
// The `dds` tracker plugin through the real dlopen path, opened and started on a host
// clock that follows the steady clock, read as the haptic loop reads it.

#include "../sim_backends/plugin_file.h"

#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mhd::dds::test {

/// The steady clock in seconds: the fake host's clock.
double steady_s();

class TrackerPluginOnClock {
 public:
  TrackerPluginOnClock(const char* plugin_file, std::initializer_list<std::pair<const char*, const char*>> params);

  /// Reads every millisecond for up to `timeout` or until `want` samples came. Each
  /// sample's timestamp must be on this host's clock: measured just now, not in the future.
  std::vector<mhd_tracker_sample> read_for(std::chrono::milliseconds timeout, std::size_t want = SIZE_MAX);
  /// The plugin's counters by name.
  std::map<std::string, std::uint64_t> counters();

 private:
  static const mhd_host& clock_now(mhd::test::FakeHost& host);

  mhd::test::PluginFile file_;
  mhd::test::FakeHost host_;
  mhd::test::StartedPlugin plugin_;
};

}  // namespace mhd::dds::test
