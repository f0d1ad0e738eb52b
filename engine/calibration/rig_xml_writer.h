#pragma once
// Writes a calibrated rig as scene XML: a copy of the file that defines the rig's robot,
// phantom and base frames, with those three frames' values replaced and a comment saying
// what was calibrated. Everything else in the file (comments, other frames, includes)
// stays. The copy is written next to `output` under a temporary name, read back with the
// scene reader and Rig::from_scene, checked against the offsets, and only then renamed to
// `output`: on any failure no file is left.
//
// The base frame (the floor under the robot) moves with the robot; only its height in the
// robot frame changes, so that with base_sensor at its nominal pose it stays on the floor
// (the rig's BaseNotOnFloor check) as SR's vertical part changes.

#include "calibration/rig_calibration.h"
#include "diagnostics/result.h"
#include "kinematics/rig.h"
#include "scene/scene_description.h"

#include <filesystem>
#include <string>
#include <vector>

namespace mhd {

/// robot -> base with `offsets`: the rig's rotation, the height that keeps base on the floor.
[[nodiscard]] Pose calibrated_X_robot_base(const Rig& rig, const RigOffsets& offsets) noexcept;

struct WrittenRig {
  std::filesystem::path frames_file;  ///< the file whose copy was written (it may be an include)
};

/// `scene` must be the one `rig` was built from (it locates the frames' file and lines).
/// `note_lines` go into the comment above the robot frame. The error says what went
/// wrong, "file:line: ..." or "file: ...", and no file is left at `output`.
[[nodiscard]] Result<WrittenRig, std::string> write_calibrated_rig(const SceneDescription& scene, const Rig& rig,
                                                                  const RigOffsets& offsets,
                                                                  const std::filesystem::path& output,
                                                                  const std::vector<std::string>& note_lines);

}  // namespace mhd
