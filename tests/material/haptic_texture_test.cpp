// The texture sampler: heights within the stated depth, slopes that are the heights'
// derivatives, friction scales within the stated contrast, height maps through their
// pixels and tiling.

#include "material/haptic_texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace mhd {
namespace {

HapticTextureSpec grating_spec() {
  HapticTextureSpec s;
  s.kind = TextureKind::Grating;
  s.depth_m = 4e-4;
  s.period_m = 3e-3;
  s.direction_uv = {1.0, 2.0};
  s.friction_contrast = 0.5;
  return s;
}

HapticTextureSpec noise_spec() {
  HapticTextureSpec s;
  s.kind = TextureKind::Noise;
  s.depth_m = 3e-4;
  s.period_m = 1e-3;
  s.max_period_m = 6e-3;
  s.seed = 7;
  s.friction_contrast = 0.3;
  return s;
}

/// 4x2 image over 8 mm x 4 mm: 2 mm texels.
HapticTexture small_map() {
  HapticTextureSpec s;
  s.kind = TextureKind::HeightMap;
  s.depth_m = 1e-3;
  s.image_size_m = {8e-3, 4e-3};
  GreyImage image;
  image.width = 4;
  image.height = 2;
  image.grey = {0.0, 0.25, 0.5, 1.0,  //
                1.0, 0.75, 0.5, 0.0};
  return HapticTexture::height_map(s, image);
}

/// Central difference of the height at uv along `axis`.
Eigen::Vector2d numeric_gradient(const HapticTexture& t, const Eigen::Vector2d& uv, double step_m) {
  const Eigen::Vector2d du(step_m, 0), dv(0, step_m);
  return {(t.sample(uv + du).height_m - t.sample(uv - du).height_m) / (2 * step_m),
          (t.sample(uv + dv).height_m - t.sample(uv - dv).height_m) / (2 * step_m)};
}

void expect_consistent(const HapticTexture& t, const HapticTextureSpec& spec) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-0.05, 0.05);
  double lowest = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector2d uv(coordinate(rng), coordinate(rng));
    const TextureSample s = t.sample(uv);
    ASSERT_LE(s.height_m, 0.0);
    ASSERT_GE(s.height_m, -spec.depth_m);
    ASSERT_GE(s.friction_scale, 1.0 - spec.friction_contrast - 1e-12);
    ASSERT_LE(s.friction_scale, 1.0 + spec.friction_contrast + 1e-12);
    const Eigen::Vector2d numeric = numeric_gradient(t, uv, 1e-7);
    ASSERT_LT((numeric - s.gradient_uv).norm(), 1e-5 * (1.0 + s.gradient_uv.norm())) << "at " << uv.transpose();
    lowest = std::min(lowest, s.height_m);
  }
  EXPECT_LT(lowest, -0.8 * spec.depth_m);  // the texture uses its depth
}

TEST(HapticTexture, GratingSlopesAreItsHeightsDerivative) {
  expect_consistent(HapticTexture::procedural(grating_spec()), grating_spec());
}

TEST(HapticTexture, NoiseSlopesAreItsHeightsDerivative) {
  expect_consistent(HapticTexture::procedural(noise_spec()), noise_spec());
}

TEST(HapticTexture, GratingRepeatsAfterOnePeriodAlongItsDirectionOnly) {
  const HapticTextureSpec spec = grating_spec();
  const HapticTexture t = HapticTexture::procedural(spec);
  const Eigen::Vector2d across = spec.direction_uv.normalized();
  const Eigen::Vector2d along(-across.y(), across.x());
  const Eigen::Vector2d uv(0.0123, -0.004);
  EXPECT_NEAR(t.sample(uv).height_m, t.sample(uv + spec.period_m * across).height_m, 1e-15);
  EXPECT_NEAR(t.sample(uv).height_m, t.sample(uv + 0.037 * along).height_m, 1e-15);
  EXPECT_NEAR(t.sample(uv + 0.5 * spec.period_m * across).height_m - t.sample(uv).height_m,
              -spec.depth_m * std::cos(2 * std::numbers::pi * across.dot(uv) / spec.period_m), 1e-12);
  EXPECT_DOUBLE_EQ(t.sample(Eigen::Vector2d::Zero()).height_m, 0.0);  // a crest at the origin
}

TEST(HapticTexture, NoiseIsFixedByItsSeed) {
  HapticTextureSpec spec = noise_spec();
  const HapticTexture a = HapticTexture::procedural(spec);
  const HapticTexture b = HapticTexture::procedural(spec);
  spec.seed = 8;
  const HapticTexture c = HapticTexture::procedural(spec);
  int differ = 0;
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector2d uv(0.0007 * i, -0.0003 * i);
    EXPECT_EQ(a.sample(uv).height_m, b.sample(uv).height_m);
    if (std::abs(a.sample(uv).height_m - c.sample(uv).height_m) > 1e-6) ++differ;
  }
  EXPECT_GT(differ, 50);
}

TEST(HapticTexture, HeightMapPassesThroughItsPixelsAndTiles) {
  const HapticTexture t = small_map();
  const double depth = t.spec().depth_m;
  // Texel (i, j) has its centre at ((i + 1/2) 2 mm, (j + 1/2) 2 mm).
  EXPECT_NEAR(t.sample({1e-3, 1e-3}).height_m, -depth, 1e-15);         // grey 0
  EXPECT_NEAR(t.sample({7e-3, 1e-3}).height_m, 0.0, 1e-15);            // grey 1
  EXPECT_NEAR(t.sample({3e-3, 3e-3}).height_m, -0.25 * depth, 1e-15);  // grey 0.75
  EXPECT_NEAR(t.sample({2e-3, 1e-3}).height_m, -0.875 * depth, 1e-15);  // halfway between 0 and 0.25
  // One image size on, in u, in v and negative: the same surface.
  for (const Eigen::Vector2d& shift : {Eigen::Vector2d(8e-3, 0), Eigen::Vector2d(0, 4e-3), Eigen::Vector2d(-16e-3, -8e-3)}) {
    EXPECT_NEAR(t.sample(Eigen::Vector2d(2.7e-3, 0.4e-3) + shift).height_m, t.sample({2.7e-3, 0.4e-3}).height_m, 1e-15);
  }
  // Across the seam: texel 3 (grey 1) wraps to texel 0 (grey 0) between u = 7 and 9 mm.
  EXPECT_NEAR(t.sample({8e-3, 1e-3}).height_m, -0.5 * depth, 1e-15);
}

TEST(HapticTexture, HeightMapSlopeIsTheCentralDifferenceAtTexelCentres) {
  const HapticTexture t = small_map();
  const double depth = t.spec().depth_m;
  // Texel (1, 0): neighbours 0 and 0.5 in u (2 mm each side); 0.75 above and below (wrapped).
  const TextureSample s = t.sample({3e-3, 1e-3});
  EXPECT_NEAR(s.gradient_uv.x(), depth * (0.5 - 0.0) / 4e-3, 1e-12);
  EXPECT_NEAR(s.gradient_uv.y(), 0.0, 1e-12);
}

TEST(HapticTexture, ProjectionsPickTheObjectAxes) {
  HapticTextureSpec spec = grating_spec();
  const Eigen::Vector3d p_O(1.0, 2.0, 3.0);
  spec.projection = TextureProjection::Xy;
  EXPECT_EQ(HapticTexture::procedural(spec).uv_of(p_O), Eigen::Vector2d(1.0, 2.0));
  spec.projection = TextureProjection::Yz;
  EXPECT_EQ(HapticTexture::procedural(spec).uv_of(p_O), Eigen::Vector2d(2.0, 3.0));
  spec.projection = TextureProjection::Zx;
  EXPECT_EQ(HapticTexture::procedural(spec).uv_of(p_O), Eigen::Vector2d(3.0, 1.0));
}

}  // namespace
}  // namespace mhd
