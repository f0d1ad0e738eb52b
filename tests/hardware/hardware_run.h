#pragma once
// What the tests of the backends for real hardware share: a scratch folder per case, a
// run's exit status, the rows of a log (a fake vendor library's, or a simulated base's or
// arm's command log), a run's summary figures, and the hardware's view of a safe end.

#include "command_log_file.h"
#include "support/mhd_run_process.h"
#include "support/scratch_dir.h"

#include <chrono>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mhd::test::hardware {

inline constexpr int kExitFault = 3;     ///< a plugin's fault ended the run
inline constexpr int kExitLastGasp = 4;  ///< a crash: the last gasp sent zero

/// The exit status once the process ended; 1000 + the signal when a signal ended it; -1
/// when it has not ended within `timeout`.
int exit_status(MhdRunProcess& process, std::chrono::seconds timeout = std::chrono::seconds(30));

/// Every row of `file`; none when it is not there.
std::vector<CommandLogRow> log_of(const std::filesystem::path& file);
/// The rows of `file` whose event is `event`.
std::vector<CommandLogRow> rows_of(const std::filesystem::path& file, const std::string& event);

/// The last "command" row of `file` (a simulated base's or arm's log) is zero.
void expect_last_command_zero(const std::filesystem::path& file, const std::string& output);

/// scenes/<name> written to dir/scene.xml: its includes of common/materials.xml and
/// rigs/pomhi.xml made absolute, its sim_omni3 base logging its commands to base.csv, then
/// each (from, to) of `fills` applied (mhd::test::fill_scene_template). Returns the path.
std::filesystem::path write_scene_logging_the_base(const std::filesystem::path& dir, const std::string& name,
                                                   std::vector<std::pair<std::string, std::string>> fills);

/// The run's ticks with force faded for stale tracking ("start-up, N stale"); -1 when the
/// summary does not say.
int stale_ticks(const std::string& output);

inline bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace mhd::test::hardware
