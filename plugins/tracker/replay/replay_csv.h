#pragma once
// Recorded tracker samples, one per CSV row:
//   timestamp_s,sensor_id,sequence,px,py,pz,qw,qx,qy,qz
// The header line is exactly those names (blanks around a name allowed); blank lines
// are skipped; line ends may be CRLF. Rows are in time order (timestamps never
// decrease), each sensor's sequence strictly increases, every number is finite and the
// quaternion has unit norm (within 1e-3; it is normalised).

#include <mhd/plugin_abi.h>

#include <filesystem>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd::tracker_replay {

/// "FILE:LINE: what is wrong" (or "FILE: ..." for the whole file).
class ReplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr const char* kReplayHeader = "timestamp_s,sensor_id,sequence,px,py,pz,qw,qx,qy,qz";

/// Reads a whole file; samples keep their recorded timestamps. Throws ReplayError.
[[nodiscard]] std::vector<mhd_tracker_sample> read_replay_csv(const std::filesystem::path& file);

/// The same from a stream; `name` stands for the file in messages.
[[nodiscard]] std::vector<mhd_tracker_sample> parse_replay_csv(std::istream& in, const std::string& name);

}  // namespace mhd::tracker_replay
