#pragma once
// Cyclone's own word on refused peers (docs/networking.md, "Counting refusals"): when a
// remote participant's credentials fail (a handshake that fails, permissions that do not
// verify), Cyclone logs an error and drops the peer; no DDS status shows it. While one
// SecurityRefusalLog lives, Cyclone's log (not its trace) goes through it: each message
// is written to stderr exactly as Cyclone's default sink writes it, and those that
// report a refused remote participant are counted. Process-wide, since Cyclone's log
// sink is; the last instance to go restores Cyclone's default sink, so no sink outlives
// the plugin that installed it. The sink also keeps Cyclone's latest error messages, so
// that a failure Cyclone reports only as "Error" can be given its real cause.

#include <cstdint>
#include <string>
#include <vector>

namespace mhd::dds {

class SecurityRefusalLog {
 public:
  SecurityRefusalLog();
  ~SecurityRefusalLog();
  SecurityRefusalLog(const SecurityRefusalLog&) = delete;
  SecurityRefusalLog& operator=(const SecurityRefusalLog&) = delete;

  /// Refusal messages Cyclone logged in this process while an instance lived.
  [[nodiscard]] static std::uint64_t refusals();
  /// How many error messages Cyclone has logged in this process while an instance lived:
  /// a mark for errors_since().
  [[nodiscard]] static std::uint64_t error_count();
  /// The error messages logged after `mark` (the latest few, oldest first, each without
  /// its header and line end).
  [[nodiscard]] static std::vector<std::string> errors_since(std::uint64_t mark);
  /// Whether a Cyclone log message reports a refused remote participant (exposed for tests).
  [[nodiscard]] static bool is_refusal(const char* message, std::uint64_t size);
};

}  // namespace mhd::dds
