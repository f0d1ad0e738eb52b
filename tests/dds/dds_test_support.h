#pragma once
// What the DDS tests share: a domain id of their own (parallel ctest runs must not hear
// each other), the loopback configuration, and child processes started with
// posix_spawn and killed when the test ends.

#include <sys/types.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <cstdint>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace mhd::dds::test {

/// Points CYCLONEDDS_URI at config/cyclonedds-loopback.xml (before any participant) and
/// returns a domain id in [1, 200] that no other running process and no earlier call of
/// this process holds: the first choice is derived from the pid and `salt`, and the
/// domain is reserved as reserve_test_domain() does.
std::uint32_t use_loopback_and_unique_domain(std::uint32_t salt = 0);

/// Reserves a domain id in [1, 200] for the rest of this process's life, starting at
/// `first_choice` and going up (wrapping) past the ones held: each id is an exclusive
/// flock on a file in the temporary directory, which the kernel releases when the
/// process ends however it ends, so no stale reservation outlives a crashed test.
/// Throws std::runtime_error when all 200 are held.
std::uint32_t reserve_test_domain(std::uint32_t first_choice);

class ChildProcess {
 public:
  /// Starts argv[0] with argv, this process's environment; stdout and stderr go to
  /// `output_file` (truncated) when given. Throws std::runtime_error.
  explicit ChildProcess(const std::vector<std::string>& argv, const std::string& output_file = {});
  ~ChildProcess();  ///< SIGKILL and reap if still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Waits up to `timeout`; the exit status, or nullopt when it is still running.
  std::optional<int> wait_for(std::chrono::milliseconds timeout);
  void kill_now();  ///< SIGKILL and reap
  void terminate();  ///< SIGTERM (does not wait)

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
};

/// Calls `step` every `period` on a thread of its own until it is destroyed (a publisher
/// standing in for another process).
class Repeating {
 public:
  Repeating(std::chrono::milliseconds period, std::function<void()> step);
  ~Repeating();
  Repeating(const Repeating&) = delete;
  Repeating& operator=(const Repeating&) = delete;

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

/// The whole content of a file ("" when it cannot be read).
std::string read_file(const std::string& path);

/// A CSV file of numbers with a header line (a haptic server recording): each row's
/// cells, read with strtod ("nan" is NaN), and the column of each name.
struct CsvTable {
  std::map<std::string, std::size_t> column;
  std::vector<std::vector<double>> rows;
  /// Row `r`'s value in column `name` (throws std::out_of_range for an unknown name).
  [[nodiscard]] double at(std::size_t r, const std::string& name) const { return rows.at(r).at(column.at(name)); }
};
CsvTable read_csv_table(const std::string& path);

/// Where t_s = 0 of a recording `mhd run --record` wrote falls in Unix time, in ns
/// (host_clock_zero_unix_ns in the .meta beside it); nullopt when the .meta has none.
/// Each process's host clock starts where its server opened: two recordings' times
/// compare only once shifted by the difference of theirs.
std::optional<std::int64_t> recording_clock_zero_unix_ns(const std::string& csv);

/// A child's output file, "<folder>/mhd_dds_test_<pid>_<name>.log", removed when the test
/// ends.
class OutputFile {
 public:
  OutputFile(const std::string& folder, const char* name);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::string text() const { return read_file(path_); }

 private:
  std::string path_;
};

}  // namespace mhd::dds::test
