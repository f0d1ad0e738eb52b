#include "rig_scale_check.h"

#include <fmt/core.h>

#include <cstddef>
#include <string>

namespace mhd::cli {

std::optional<Diagnostic> check_rig_scale(const SceneDescription& scene) {
  const FrameDescription* farthest = nullptr;
  std::size_t offset_frames = 0;
  for (const FrameDescription& f : scene.rig_frames) {
    const double d_m = f.X_PF.translation().norm();
    if (d_m == 0.0) continue;  // a frame that only turns says nothing about the unit
    ++offset_frames;
    if (farthest == nullptr || d_m > farthest->X_PF.translation().norm()) farthest = &f;
  }
  if (farthest == nullptr) return std::nullopt;
  const double d_m = farthest->X_PF.translation().norm();
  if (d_m > kFarthestPlausibleFrame_m) {
    return Diagnostic{farthest->where,
                      fmt::format("rig frame '{}' is {:.4g} m from '{}': is the scene's unit right? (millimetre "
                                  "values in a unit=\"m\" scene are 1000x too large)",
                                  farthest->name, d_m, farthest->parent)};
  }
  if (d_m < kNearestPlausibleRig_m) {
    const std::string which = offset_frames == 1
                                  ? std::string("the only rig frame with an offset is within 5 mm of its parent")
                                  : fmt::format("all {} rig frames with an offset are within 5 mm of their parents",
                                                offset_frames);
    return Diagnostic{farthest->where,
                      fmt::format("{} ('{}' is {:.3g} mm from '{}'): is the scene's unit right? (metre values in "
                                  "a unit=\"mm\" scene are 1000x too small)",
                                  which, farthest->name, d_m * 1e3, farthest->parent)};
  }
  return std::nullopt;
}

}  // namespace mhd::cli
