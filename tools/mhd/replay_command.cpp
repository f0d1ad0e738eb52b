// `mhd replay RECORDING.csv [--scene SCENE.xml] [--out REPLAYED.csv]`: feeds a recording's
// inputs (joint angles, base pose, tracker age, tick interval) back through the haptic
// tick and compares what comes out with what was recorded (engine/haptic_server/
// recording_replay.h). The scene defaults to the one `mhd run` names in RECORDING.csv.meta.
// Exit status 0 when every force, proxy and torque is identical, 1 when they differ or
// the input is bad.

#include "replay_command.h"

#include "command_scene.h"

#include "command_exit.h"
#include "haptic_server/recording_replay.h"
#include "haptic_server/server_settings.h"
#include "recording/csv_recording.h"
#include "recording/csv_recording_reader.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <fmt/core.h>

#include <fstream>
#include <memory>
#include <string>

namespace {

struct ReplayOptions {
  std::string recording;
  std::string scene;
  std::string out;
};

/// "scene=PATH" from the recording's .meta file, or "".
std::string scene_from_meta(const std::string& recording) {
  std::ifstream meta(recording + ".meta");
  for (std::string line; std::getline(meta, line);) {
    if (line.rfind("scene=", 0) == 0) return line.substr(6);
  }
  return {};
}

int replay(const ReplayOptions& opt) {
  const std::string scene_file = opt.scene.empty() ? scene_from_meta(opt.recording) : opt.scene;
  if (scene_file.empty()) {
    fmt::print(stderr, "mhd replay: error: {}: no --scene given and no {}.meta naming one\n", opt.recording,
               opt.recording);
    return 1;
  }
  const mhd::Result<std::vector<mhd::RecordingRow>> recording = mhd::read_recording(opt.recording);
  for (const auto& d : recording.diagnostics()) fmt::print(stderr, "mhd replay: error: {}\n", d.to_string());
  if (!recording.ok()) return 1;

  const std::optional<mhd::SceneDescription> read = mhd::cli::read_command_scene(scene_file);
  if (!read) return 1;
  if (read->sharing) {
    // Its replicas moved as the other rigs' states said, which no recording holds.
    const mhd::Diagnostic refused{read->sharing->where,
                                  "the scene shares objects with other rigs (<sharing>); a replay cannot rerun them: "
                                  "the other rigs' states and pushes are not in the recording"};
    fmt::print(stderr, "mhd replay: error: {}\n", refused.to_string());
    return 1;
  }
  const std::unique_ptr<mhd::CompiledScene> compiled = mhd::cli::compile_command_scene(*read);
  if (!compiled) return 1;
  const mhd::Result<mhd::Rig, std::vector<mhd::RigError>> rig = mhd::Rig::from_scene(*read);
  if (!rig.ok()) fmt::print(stderr, "{}\n", rig.error_text());
  const mhd::Result<mhd::ServerSettings> settings = mhd::server_settings_from(*read);
  for (const auto& d : settings.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
  if (!rig.ok() || !settings.ok()) return 1;

  const mhd::ReplayComparison r =
      mhd::replay_recording(*compiled, *rig, settings->tick, recording.value());
  fmt::print("replayed {} rows of {} on {}\n", r.rows, opt.recording, scene_file);
  fmt::print("max difference: force {:.3g} N, proxy {:.3g} m, device force {:.3g} N; {} rows differ\n",
             r.max_force_difference_N, r.max_proxy_difference_m, r.max_device_force_difference_N, r.differing_rows);
  if (!opt.out.empty()) {
    try {
      mhd::CsvRecording out(opt.out, 1.0);
      for (const auto& row : r.replayed) out.write(row);
      out.flush();
    } catch (const std::exception& e) {
      fmt::print(stderr, "mhd replay: error: {}\n", e.what());
      return 1;
    }
  }
  if (r.differing_rows > 0) {
    fmt::print(stderr, "mhd replay: error: {}:{}: the replay differs from the recording from this row on\n",
               opt.recording, r.first_differing_row + 2);  // + header, 1-based
    return 1;
  }
  fmt::print("identical: the same inputs gave the same forces\n");
  return 0;
}

}  // namespace

void add_replay_command(CLI::App& app) {
  auto opt = std::make_shared<ReplayOptions>();
  CLI::App* cmd = app.add_subcommand("replay", "Re-run a recording through the engine and compare the forces");
  cmd->add_option("recording", opt->recording, "Recording CSV written by mhd run --record")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--scene", opt->scene, "Scene XML (default: the one named in RECORDING.csv.meta)");
  cmd->add_option("--out", opt->out, "Write the replayed rows as a recording to this file");
  cmd->callback([opt] { mhd::cli::exit_with(replay(*opt)); });
}
