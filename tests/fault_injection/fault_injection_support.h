#pragma once
// Helpers of the fault-injection suite: scenes on the thesis rig with a block the probe
// device presses into, running the server through the real dlopen path, the probe
// plugins' logs, and a child process for `mhd run`.

#include "haptic_server/haptic_server.h"
#include "recording/recording_row.h"
#include "scene/scene_description.h"
#include "scene_compiler/compiled_scene.h"

#include <Eigen/Core>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace mhd::fault_injection_test {

namespace fs = std::filesystem;

/// A folder of its own for the running test case (ctest runs cases in parallel, each in
/// its own process: the pid keeps two runs of one case apart too).
fs::path temp_dir();

/// Joint angles of the probe device: free (HIP above the block) and pressing (HIP
/// `depth_m` into the block's top face), and the block that makes it so. Computed with
/// the rig of scenes/rigs/pomhi.xml, the base at the origin.
struct PressGeometry {
  Eigen::Vector3d q_free_rad;
  Eigen::Vector3d q_press_rad;
  Eigen::Vector3d p_free_P_m;   ///< the tool at q_free_rad, device frame: what fi_device reports
  Eigen::Vector3d p_press_P_m;  ///< likewise at q_press_rad
  Eigen::Vector3d hip_free_W_m;
  Eigen::Vector3d hip_press_W_m;
  double block_top_y_m = 0.0;
};
PressGeometry press_geometry(double depth_m);

/// Writes `dir`/scene.xml: the rig, a 1.6 m x 0.2 m x 1.6 m block (stiffness 1000 N/m)
/// under the pressing HIP, the given <plugins> content and <server> params, and
/// `scene_elements` (e.g. a <haptics/>) at the scene's level.
fs::path write_scene(const fs::path& dir, const PressGeometry& g, const std::string& plugins,
                     const std::string& server_params, const std::string& scene_elements = "");

/// The fi_device <plugin> element: presses from press_at_s over 0.05 s; `extra` is
/// more <param> lines (faults).
std::string fi_device_xml(const PressGeometry& g, const fs::path& log, double press_at_s, const std::string& extra = "");

struct Loaded {
  std::optional<SceneDescription> description;
  std::optional<CompiledScene> scene;
};
/// Reads and compiles; every diagnostic is a test failure.
Loaded load(const fs::path& file);

/// Opens the scene's plugins (from the suite's plugin folder) and runs it.
struct RunResult {
  bool opened = false;
  Diagnostics warnings;  ///< HapticServer::open's
  ServerReport report;
  ServerSettings settings;
};
RunResult run_server(const Loaded& scene, double duration_s, const fs::path& recording, const BasePlanFn& plan);

/// The 1-based line of the first line of `file` containing `text` (0: none).
int line_of(const fs::path& file, const std::string& text);

/// One line of a probe log: time and three values; a fault marker has NaN values.
struct LogRow {
  double t_s = 0.0;
  double a = 0.0, b = 0.0, c = 0.0;
  [[nodiscard]] bool is_zero() const { return a == 0.0 && b == 0.0 && c == 0.0; }
  [[nodiscard]] bool is_marker() const;
};
std::vector<LogRow> read_log(const fs::path& file);

/// The recording, through engine/recording's reader; a diagnostic is a test failure.
std::vector<RecordingRow> read_rows(const fs::path& file);

[[nodiscard]] double force_N(const RecordingRow& r);

/// A child process with stdout and stderr into a file; SIGKILLed and reaped at the end.
class ChildProcess {
 public:
  ChildProcess(const std::vector<std::string>& argv, const fs::path& working_dir, const fs::path& output);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  /// SIGKILL; returns the steady-clock time just before the signal was sent.
  std::chrono::steady_clock::time_point kill9();
  /// The raw wait status once the process has ended (waits up to `timeout`).
  std::optional<int> wait_for(std::chrono::milliseconds timeout);
  [[nodiscard]] pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
};

}  // namespace mhd::fault_injection_test
