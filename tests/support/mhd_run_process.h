#pragma once
// `mhd run` as a child process for the end-of-run tests: its output in a file, signals to
// send, its exit status, and a wait for the hardware's log to show the run under way.

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mhd::test {

/// The scene `source` (a file under the source tree) as text for a test folder: its
/// include of scenes/rigs/pomhi.xml made absolute, then each (from, to) of `fills` put in
/// where `from` first stands. A `from` that is not there throws std::runtime_error.
std::string fill_scene_template(const std::filesystem::path& source,
                                const std::vector<std::pair<std::string, std::string>>& fills);

class MhdRunProcess {
 public:
  struct Options {
    std::vector<std::string> argv;                           ///< argv[0] is the program
    std::filesystem::path dir;                               ///< working folder; output.txt goes here
    std::vector<std::pair<std::string, std::string>> env{};  ///< set in the child
    bool stdout_to_closed_pipe = false;                      ///< stdout a pipe nobody reads
  };
  explicit MhdRunProcess(const Options& options);
  ~MhdRunProcess();  ///< SIGKILL if still running
  MhdRunProcess(const MhdRunProcess&) = delete;
  MhdRunProcess& operator=(const MhdRunProcess&) = delete;

  /// Waits (up to 30 s) until `log` in the working folder has `rows` rows of the given
  /// event ("" for any), read with read_command_log. False if the process ended first or
  /// the time ran out.
  bool wait_until_logged(const std::string& log, std::size_t rows, const std::string& event = "");
  void signal(int s) const;
  /// The raw wait status once the process has ended, or nothing within `timeout`.
  std::optional<int> wait_for(std::chrono::milliseconds timeout);
  [[nodiscard]] std::string output() const;

 private:
  std::filesystem::path dir_;
  pid_t pid_ = -1;
  std::optional<int> status_;
};

}  // namespace mhd::test
