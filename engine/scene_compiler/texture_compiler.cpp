#include "scene_compiler/texture_compiler.h"

#include "scene/plausible_bounds.h"
#include "scene_compiler/grey_png.h"

#include <fmt/format.h>

#include <cmath>

namespace mhd {
namespace {

bool within(double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; }

std::string check(const HapticTextureSpec& spec) {
  if (!within(spec.depth_m, 0.0, kMaxTextureDepth_m)) {
    return fmt::format("depth must be within [0, {}] m (got {})", kMaxTextureDepth_m, spec.depth_m);
  }
  if (!within(spec.friction_contrast, 0.0, 1.0)) {
    return fmt::format("friction contrast must be within [0, 1] (got {})", spec.friction_contrast);
  }
  if (spec.kind == TextureKind::HeightMap) {
    if (!within(spec.image_size_m.x(), kMinTexturePeriod_m, kMaxTexturePeriod_m) ||
        !within(spec.image_size_m.y(), kMinTexturePeriod_m, kMaxTexturePeriod_m)) {
      return fmt::format("image size must be within [{}, {}] m (got {} x {})", kMinTexturePeriod_m,
                         kMaxTexturePeriod_m, spec.image_size_m.x(), spec.image_size_m.y());
    }
    return {};
  }
  if (!within(spec.period_m, kMinTexturePeriod_m, kMaxTexturePeriod_m)) {
    return fmt::format("period must be within [{}, {}] m (got {})", kMinTexturePeriod_m, kMaxTexturePeriod_m,
                       spec.period_m);
  }
  if (spec.kind == TextureKind::Noise && !within(spec.max_period_m, spec.period_m, kMaxTexturePeriod_m)) {
    return fmt::format("longest period must be within [{}, {}] m (got {})", spec.period_m, kMaxTexturePeriod_m,
                       spec.max_period_m);
  }
  if (spec.kind == TextureKind::Grating &&
      (!spec.direction_uv.allFinite() || spec.direction_uv.cwiseAbs().maxCoeff() == 0.0)) {
    return "grating direction must be finite and not zero";
  }
  return {};
}

}  // namespace

std::string compile_texture(const HapticTextureSpec& spec, std::shared_ptr<const HapticTexture>& texture) {
  if (std::string problem = check(spec); !problem.empty()) return problem;
  if (spec.kind != TextureKind::HeightMap) {
    texture = std::make_shared<const HapticTexture>(HapticTexture::procedural(spec));
    return {};
  }
  GreyImage image;
  if (std::string problem = read_grey_png(spec.image_file, image); !problem.empty()) return problem;
  texture = std::make_shared<const HapticTexture>(HapticTexture::height_map(spec, std::move(image)));
  return {};
}

}  // namespace mhd
