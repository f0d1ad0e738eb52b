#pragma once
// What a fault plugin (tests/haptic_server/plugins) logs at close: "count a b c", how
// many commands it got and the last one's three values.

#include <filesystem>
#include <fstream>

namespace mhd::test {

struct FaultPluginLog {
  unsigned long count = 0;
  double a = 1, b = 1, c = 1;
};

inline FaultPluginLog read_fault_plugin_log(const std::filesystem::path& file) {
  FaultPluginLog log;
  std::ifstream in(file);
  in >> log.count >> log.a >> log.b >> log.c;
  return log;
}

}  // namespace mhd::test
