// libFuzzer target: the tracker replay CSV reader (plugins/tracker/replay/replay_csv.h).
//
// Invariants (a violation traps):
//  - parse_replay_csv() either returns samples or throws ReplayError; nothing else escapes;
//  - a rejection's message starts with the file name and, for a problem on a line, names
//    a line that exists ("NAME:LINE: ..." with 1 <= LINE <= lines in the input), and says
//    something after the prefix;
//  - accepted samples: at least one, all numbers finite, unit quaternions (normalised),
//    timestamps never decreasing, each sensor's sequence strictly increasing.
#include "replay_csv.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr const char* kName = "fuzz_input.csv";

[[noreturn]] void violated(const std::string& what) {
  std::fprintf(stderr, "\n*** mhd-fuzz-replay-csv: invariant violated: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

/// Lines std::getline() would read from `text`.
std::size_t getline_count(std::string_view text) {
  std::size_t n = 0;
  for (const char c : text) n += c == '\n' ? 1u : 0u;
  if (!text.empty() && text.back() != '\n') ++n;
  return n;
}

void check_message(const std::string& message, std::string_view input) {
  const std::string prefix = std::string(kName) + ":";
  if (message.rfind(prefix, 0) != 0) violated("message does not start with the file name: " + message);
  std::string_view rest = std::string_view(message).substr(prefix.size());
  if (!rest.empty() && rest.front() >= '0' && rest.front() <= '9') {
    std::size_t line = 0;
    std::size_t i = 0;
    while (i < rest.size() && rest[i] >= '0' && rest[i] <= '9' && line < 1000000000) {
      line = line * 10 + static_cast<std::size_t>(rest[i] - '0');
      ++i;
    }
    if (i >= rest.size() || rest[i] != ':') violated("malformed location in: " + message);
    if (line < 1 || line > getline_count(input)) {
      violated("line " + std::to_string(line) + " outside the input's " + std::to_string(getline_count(input)) +
               " lines: " + message);
    }
    rest.remove_prefix(i + 1);
  }
  if (rest.size() < 3 || rest.front() != ' ') violated("no description after the location: " + message);
}

void check_samples(const std::vector<mhd_tracker_sample>& samples) {
  if (samples.empty()) violated("accepted a file without samples");
  std::map<std::uint32_t, std::uint64_t> last_sequence;
  double last_time = -std::numeric_limits<double>::infinity();
  for (const mhd_tracker_sample& s : samples) {
    if (!std::isfinite(s.timestamp_s)) violated("timestamp not finite");
    if (s.timestamp_s < last_time) violated("timestamps go back");
    last_time = s.timestamp_s;
    double norm2 = 0.0;
    for (const double p : s.p_T_m) {
      if (!std::isfinite(p)) violated("position not finite");
    }
    for (const double q : s.q_T_wxyz) {
      if (!std::isfinite(q)) violated("quaternion not finite");
      norm2 += q * q;
    }
    if (std::abs(std::sqrt(norm2) - 1.0) > 1e-9) violated("quaternion not normalised: |q| = " + std::to_string(std::sqrt(norm2)));
    const auto [it, first] = last_sequence.emplace(s.sensor_id, s.sequence);
    if (!first) {
      if (s.sequence <= it->second) violated("sequence does not increase for sensor " + std::to_string(s.sensor_id));
      it->second = s.sequence;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::istringstream in{std::string(input)};
  try {
    check_samples(mhd::tracker_replay::parse_replay_csv(in, kName));
  } catch (const mhd::tracker_replay::ReplayError& e) {
    check_message(e.what(), input);
  } catch (const std::exception& e) {
    violated(std::string("an exception other than ReplayError: ") + e.what());
  }
  return 0;
}
