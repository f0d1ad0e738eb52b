#pragma once
// Re-runs a recording through the haptic tick: each row's joint angles, base pose,
// tracker age and tick interval go into HapticTick::render, in order, from a fresh proxy
// and safety state, and the forces, proxy positions and device forces that come out are
// compared with the recorded ones. Recordings store numbers in round-trip form, so the
// same engine gives bit-identical results; any difference means the engine, the scene or
// the settings changed (or rows were dropped while recording).

#include "haptic_server/haptic_tick.h"
#include "kinematics/rig.h"
#include "recording/recording_row.h"
#include "scene_compiler/compiled_scene.h"

#include <cstddef>
#include <vector>

namespace mhd {

struct ReplayComparison {
  std::vector<RecordingRow> replayed;  ///< the recomputed rows (user pose copied)
  std::size_t rows = 0;
  std::size_t differing_rows = 0;     ///< rows whose force, proxy or device force differ at all
  std::size_t first_differing_row = 0;  ///< 0-based; meaningful when differing_rows > 0
  double max_force_difference_N = 0.0;
  double max_proxy_difference_m = 0.0;
  double max_device_force_difference_N = 0.0;
};

[[nodiscard]] ReplayComparison replay_recording(const CompiledScene& scene, const Rig& rig,
                                            const HapticTickSettings& settings, const std::vector<RecordingRow>& rows);

}  // namespace mhd
