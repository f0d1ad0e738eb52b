#include "viewer/viewer_options.h"

#include <fmt/core.h>

#include <cmath>

namespace mhd::viewer {

std::string ViewerOptions::check() const {
  if (!(std::isfinite(ipd_m) && ipd_m >= 0.0 && ipd_m <= 0.2)) return fmt::format("ipd_m must be in [0, 0.2], got {}", ipd_m);
  if (!(std::isfinite(fov_deg) && fov_deg >= 10.0 && fov_deg <= 170.0)) {
    return fmt::format("fov_deg must be in [10, 170], got {}", fov_deg);
  }
  if (width < 16 || width > 16384 || height < 16 || height > 16384) {
    return fmt::format("image size must be 16..16384 pixels per side, got {}x{}", width, height);
  }
  if (!(std::isfinite(max_frame_rate_Hz) && max_frame_rate_Hz >= 0.0)) {
    return fmt::format("max_frame_rate_Hz must be >= 0, got {}", max_frame_rate_Hz);
  }
  if (frames < 0) return fmt::format("frames must be >= 0, got {}", frames);
  if (!screenshot_png.empty() && frames < 1) return "a screenshot needs frames >= 1";
  if (!(std::isfinite(force_scale_m_per_N) && force_scale_m_per_N >= 0.0)) {
    return fmt::format("force_scale_m_per_N must be >= 0, got {}", force_scale_m_per_N);
  }
  if (!(near_m > 0.0 && far_m > near_m && std::isfinite(far_m))) {
    return fmt::format("clip planes need 0 < near_m < far_m, got {} and {}", near_m, far_m);
  }
  if (default_head_m && !default_head_m->allFinite()) return "default head position must be finite";
  if (look_at_m && !look_at_m->allFinite()) return "look-at point must be finite";
  return {};
}

}  // namespace mhd::viewer
