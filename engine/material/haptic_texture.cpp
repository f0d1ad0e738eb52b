#include "material/haptic_texture.h"

#include <cmath>
#include <numbers>
#include <random>
#include <utility>

namespace mhd {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Uniform in [0, 1) from the generator's raw bits: std::mt19937_64's output is fixed by
/// the standard, the distributions' mapping is not, so a seed gives one surface everywhere.
double unit_uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

/// Index of `x` wrapped into [0, n).
int wrap(int x, int n) {
  const int r = x % n;
  return r < 0 ? r + n : r;
}

}  // namespace

HapticTexture HapticTexture::procedural(const HapticTextureSpec& spec) {
  HapticTexture texture(spec);
  if (spec.kind == TextureKind::Grating) {
    texture.waves_[0].wavenumber_rad_per_m = (kTwoPi / spec.period_m) * spec.direction_uv.normalized();
    texture.wave_count_ = 1;
    return texture;
  }
  // Noise: wavenumbers log-uniform over the band, directions and phases uniform.
  std::mt19937_64 rng(spec.seed);
  const double k_min = kTwoPi / spec.max_period_m;
  const double k_max = kTwoPi / spec.period_m;
  for (Wave& wave : texture.waves_) {
    const double k = k_min * std::pow(k_max / k_min, unit_uniform(rng));
    const double angle = kTwoPi * unit_uniform(rng);
    wave.wavenumber_rad_per_m = k * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    wave.phase_rad = kTwoPi * unit_uniform(rng);
  }
  texture.wave_count_ = kNoiseComponents;
  return texture;
}

HapticTexture HapticTexture::height_map(const HapticTextureSpec& spec, GreyImage image) {
  HapticTexture texture(spec);
  const int w = image.width;
  const int h = image.height;
  const double du_m = spec.image_size_m.x() / w;
  const double dv_m = spec.image_size_m.y() / h;
  // Central differences with wrap-around (the image tiles): interpolated between texel
  // centres they give a slope that is continuous, unlike the bilinear surface's own.
  texture.image_slope_per_m_.resize(image.grey.size());
  const auto at = [&](int i, int j) { return image.grey[static_cast<std::size_t>(wrap(j, h) * w + wrap(i, w))]; };
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      texture.image_slope_per_m_[static_cast<std::size_t>(j * w + i)] =
          Eigen::Vector2d((at(i + 1, j) - at(i - 1, j)) / (2.0 * du_m), (at(i, j + 1) - at(i, j - 1)) / (2.0 * dv_m));
    }
  }
  texture.image_ = std::move(image);
  return texture;
}

void HapticTexture::relief(const Eigen::Vector2d& uv_m, double& r, Eigen::Vector2d& dr_duv) const {
  if (spec_.kind == TextureKind::HeightMap) {
    const int w = image_.width;
    const int h = image_.height;
    // Texel (i, j) has its centre at ((i + 1/2) / w, (j + 1/2) / h) of the image's size.
    const double x = uv_m.x() / spec_.image_size_m.x() * w - 0.5;
    const double y = uv_m.y() / spec_.image_size_m.y() * h - 0.5;
    const double x0 = std::floor(x);
    const double y0 = std::floor(y);
    const double fx = x - x0;
    const double fy = y - y0;
    // fmod first: a coordinate far out must not overflow int.
    const int i0 = wrap(static_cast<int>(std::fmod(x0, static_cast<double>(w))), w);
    const int j0 = wrap(static_cast<int>(std::fmod(y0, static_cast<double>(h))), h);
    const int i1 = wrap(i0 + 1, w);
    const int j1 = wrap(j0 + 1, h);
    const auto idx = [w](int i, int j) { return static_cast<std::size_t>(j * w + i); };
    const double w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
    r = w00 * image_.grey[idx(i0, j0)] + w10 * image_.grey[idx(i1, j0)] + w01 * image_.grey[idx(i0, j1)] +
        w11 * image_.grey[idx(i1, j1)];
    dr_duv = w00 * image_slope_per_m_[idx(i0, j0)] + w10 * image_slope_per_m_[idx(i1, j0)] +
             w01 * image_slope_per_m_[idx(i0, j1)] + w11 * image_slope_per_m_[idx(i1, j1)];
    return;
  }
  if (spec_.kind == TextureKind::Grating) {
    const Wave& wave = waves_[0];
    const double phase = wave.wavenumber_rad_per_m.dot(uv_m);
    r = 0.5 * (1.0 + std::cos(phase));
    dr_duv = -0.5 * std::sin(phase) * wave.wavenumber_rad_per_m;
    return;
  }
  // Noise: s, a sum of unit sinusoids scaled to unit variance, squashed by tanh into
  // (0, 1) so that depth_m bounds it while typical values still use most of the depth.
  double s = 0.0;
  Eigen::Vector2d ds = Eigen::Vector2d::Zero();
  for (int i = 0; i < wave_count_; ++i) {
    const Wave& wave = waves_[static_cast<std::size_t>(i)];
    const double phase = wave.wavenumber_rad_per_m.dot(uv_m) + wave.phase_rad;
    s += std::cos(phase);
    ds -= std::sin(phase) * wave.wavenumber_rad_per_m;
  }
  const double scale = 1.0 / std::sqrt(0.5 * wave_count_);
  const double t = std::tanh(s * scale);
  r = 0.5 * (1.0 + t);
  dr_duv = 0.5 * (1.0 - t * t) * scale * ds;
}

TextureSample HapticTexture::sample(const Eigen::Vector2d& uv_m) const {
  double r = 1.0;
  Eigen::Vector2d dr = Eigen::Vector2d::Zero();
  relief(uv_m, r, dr);
  TextureSample out;
  out.height_m = spec_.depth_m * (r - 1.0);
  out.gradient_uv = spec_.depth_m * dr;
  out.friction_scale = 1.0 + spec_.friction_contrast * (2.0 * r - 1.0);
  return out;
}

Eigen::Vector2d HapticTexture::uv_of(const Eigen::Vector3d& p_O) const {
  return {u_axis_O().dot(p_O), v_axis_O().dot(p_O)};
}

Eigen::Vector3d HapticTexture::u_axis_O() const {
  switch (spec_.projection) {
    case TextureProjection::Yz: return Eigen::Vector3d::UnitY();
    case TextureProjection::Zx: return Eigen::Vector3d::UnitZ();
    case TextureProjection::Xy: break;
  }
  return Eigen::Vector3d::UnitX();
}

Eigen::Vector3d HapticTexture::v_axis_O() const {
  switch (spec_.projection) {
    case TextureProjection::Yz: return Eigen::Vector3d::UnitZ();
    case TextureProjection::Zx: return Eigen::Vector3d::UnitX();
    case TextureProjection::Xy: break;
  }
  return Eigen::Vector3d::UnitY();
}

}  // namespace mhd
