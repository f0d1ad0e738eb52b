// Haptic textures through the god-object: a stroke over a flat plate at constant speed
// and depth must carry the texture's spatial frequency, speed / period, in its force
// spectrum, and only when the texture is there.

#include "proxy/god_object.h"
#include "proxy/texture_force.h"
#include "proxy_test_rig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <vector>

namespace mhd::test {
namespace {

constexpr double kRate_Hz = 1000.0;
constexpr double kSpeed_m_per_s = 0.05;
constexpr double kPressDepth_m = 0.002;
constexpr int kStrokeTicks = 1000;  // 1 s: bins 1 Hz apart

HapticMaterial textured(const HapticTextureSpec& spec, double mu_static = 0.0, double mu_dynamic = 0.0) {
  HapticMaterial m = stiff(1000.0);
  m.static_friction = mu_static;
  m.dynamic_friction = mu_dynamic;
  m.texture_spec = spec;
  m.texture = std::make_shared<HapticTexture>(HapticTexture::procedural(spec));
  return m;
}

HapticTextureSpec grating(double period_m, double depth_m) {
  HapticTextureSpec spec;
  spec.kind = TextureKind::Grating;
  spec.period_m = period_m;
  spec.depth_m = depth_m;
  return spec;
}

struct StrokeForces {
  std::vector<double> tangential_N;  ///< along the stroke (x)
  std::vector<double> normal_N;      ///< along the plate's normal (z)
  int contact_ticks = 0;
};

/// Presses 2 mm into the plate z = 0 (facing +z) and strokes along +x at constant speed;
/// records the force of the stroke's ticks only (after 200 ticks of settling).
StrokeForces stroke_plate(const HapticMaterial& material) {
  ProxyRig rig;
  rig.add(quad({-0.2, -0.2, 0}, {0.2, -0.2, 0}, {0.2, 0.2, 0}, {-0.2, 0.2, 0}), material);
  const Eigen::Vector3d start(-0.1, 0.013, 0.01);
  const Eigen::Vector3d pressed(-0.1, 0.013, -kPressDepth_m);
  reset_proxy(rig.state, start);
  rig.move(start, pressed, 100);
  const double dx_m = kSpeed_m_per_s / kRate_Hz;
  for (int i = 1; i <= 200; ++i) rig.step(pressed + Eigen::Vector3d(dx_m * i, 0, 0));  // reach steady sliding
  StrokeForces out;
  for (int i = 1; i <= kStrokeTicks; ++i) {
    const ProxyOutput o = rig.step(pressed + Eigen::Vector3d(dx_m * (200 + i), 0, 0));
    out.tangential_N.push_back(o.force_W.x());
    out.normal_N.push_back(o.force_W.z());
    if (o.in_contact) ++out.contact_ticks;
  }
  return out;
}

/// |DFT| of the signal less its mean, bins 0 .. n/2.
std::vector<double> amplitude_spectrum(const std::vector<double>& x) {
  const std::size_t n = x.size();
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  std::vector<double> amplitude(n / 2 + 1);
  for (std::size_t k = 0; k < amplitude.size(); ++k) {
    std::complex<double> sum = 0.0;
    for (std::size_t t = 0; t < n; ++t) {
      const double angle = -2.0 * std::numbers::pi * static_cast<double>(k * t) / static_cast<double>(n);
      sum += (x[t] - mean) * std::polar(1.0, angle);
    }
    amplitude[k] = 2.0 * std::abs(sum) / static_cast<double>(n);
  }
  return amplitude;
}

std::size_t peak_bin(const std::vector<double>& amplitude) {
  std::size_t best = 1;
  for (std::size_t k = 1; k < amplitude.size(); ++k) {
    if (amplitude[k] > amplitude[best]) best = k;
  }
  return best;
}

double bin_width_Hz() { return kRate_Hz / kStrokeTicks; }

TEST(TextureForce, GratingsSpatialFrequencyIsTheTangentialForcesPeak) {
  const double period_m = 0.002;
  const StrokeForces f = stroke_plate(textured(grating(period_m, 2e-4)));
  ASSERT_EQ(f.contact_ticks, kStrokeTicks);
  const std::vector<double> a = amplitude_spectrum(f.tangential_N);
  const double expected_Hz = kSpeed_m_per_s / period_m;
  EXPECT_NEAR(static_cast<double>(peak_bin(a)) * bin_width_Hz(), expected_Hz, bin_width_Hz());
  EXPECT_GT(a[peak_bin(a)], 0.1);  // a force a hand feels, not rounding
}

TEST(TextureForce, GratingsSpatialFrequencyIsTheNormalForcesPeakForAnyPeriod) {
  for (const double period_m : {0.001, 0.0025, 0.005}) {
    // Slopes up to 0.16 (depth a twentieth of the period): steeper ridges turn the force
    // so far that its normal part's second harmonic takes over.
    const StrokeForces f = stroke_plate(textured(grating(period_m, period_m / 20)));
    const std::vector<double> a = amplitude_spectrum(f.normal_N);
    EXPECT_NEAR(static_cast<double>(peak_bin(a)) * bin_width_Hz(), kSpeed_m_per_s / period_m, bin_width_Hz())
        << "period " << period_m << " m";
  }
}

TEST(TextureForce, WithoutATextureTheSameStrokeHasNoSuchPeak) {
  const double period_m = 0.002;
  const std::size_t bin = static_cast<std::size_t>(std::lround(kSpeed_m_per_s / period_m / bin_width_Hz()));
  const StrokeForces smooth = stroke_plate(stiff(1000.0));
  const StrokeForces rough = stroke_plate(textured(grating(period_m, 2e-4)));
  ASSERT_EQ(smooth.contact_ticks, kStrokeTicks);
  const double smooth_amplitude = amplitude_spectrum(smooth.tangential_N)[bin];
  const double rough_amplitude = amplitude_spectrum(rough.tangential_N)[bin];
  EXPECT_LT(smooth_amplitude, 1e-3 * rough_amplitude);
  EXPECT_LT(amplitude_spectrum(smooth.normal_N)[bin], 1e-3 * amplitude_spectrum(rough.normal_N)[bin]);
}

TEST(TextureForce, TheTextureNeverAddsNormalForceToTheSmoothSurfaces) {
  const StrokeForces smooth = stroke_plate(stiff(1000.0));
  const StrokeForces rough = stroke_plate(textured(grating(0.002, 5e-4)));
  double lowest_N = smooth.normal_N[0];
  for (std::size_t i = 0; i < rough.normal_N.size(); ++i) {
    const Eigen::Vector2d f(rough.tangential_N[i], rough.normal_N[i]);
    EXPECT_LE(f.norm(), smooth.normal_N[i] + 1e-9) << "tick " << i;
    lowest_N = std::min(lowest_N, rough.normal_N[i]);
  }
  // The valleys, 0.5 mm deep at 1 N/mm, take up to 0.5 N off the 2 N press.
  EXPECT_LT(lowest_N, smooth.normal_N[0] - 0.4);
}

TEST(TextureForce, AFrictionMapPutsItsPeriodInTheFrictionForce) {
  HapticTextureSpec map = grating(0.002, 0.0);  // no relief: friction only
  map.friction_contrast = 0.8;
  HapticTextureSpec flat = map;
  flat.friction_contrast = 0.0;
  const StrokeForces mapped = stroke_plate(textured(map, 0.5, 0.4));
  const StrokeForces uniform = stroke_plate(textured(flat, 0.5, 0.4));
  const std::vector<double> a = amplitude_spectrum(mapped.tangential_N);
  const double expected_Hz = kSpeed_m_per_s / 0.002;
  EXPECT_NEAR(static_cast<double>(peak_bin(a)) * bin_width_Hz(), expected_Hz, bin_width_Hz());
  const std::size_t bin = static_cast<std::size_t>(std::lround(expected_Hz / bin_width_Hz()));
  EXPECT_LT(amplitude_spectrum(uniform.tangential_N)[bin], 0.05 * a[bin]);
  // The dynamic friction force opposes the stroke (the HIP leads the proxy along +x).
  double mean_N = 0.0;
  for (double v : mapped.tangential_N) mean_N += v / kStrokeTicks;
  EXPECT_LT(mean_N, -0.1);
}

TEST(TextureForce, NoiseIsTheSameForOneSeedAndDiffersForAnother) {
  HapticTextureSpec noise;
  noise.kind = TextureKind::Noise;
  noise.depth_m = 3e-4;
  noise.period_m = 0.001;
  noise.max_period_m = 0.005;
  noise.seed = 42;
  const StrokeForces a = stroke_plate(textured(noise));
  const StrokeForces b = stroke_plate(textured(noise));
  noise.seed = 43;
  const StrokeForces c = stroke_plate(textured(noise));
  EXPECT_EQ(a.tangential_N, b.tangential_N);
  EXPECT_EQ(a.normal_N, b.normal_N);
  double differ_N = 0.0;
  for (std::size_t i = 0; i < a.normal_N.size(); ++i) differ_N = std::max(differ_N, std::abs(a.normal_N[i] - c.normal_N[i]));
  EXPECT_GT(differ_N, 0.05);
}

TEST(TextureForce, TheProxyPathIsTheSmoothSurfacesWhateverTheTexture) {
  // The texture shapes the force only: the proxy moves exactly as over the smooth plate.
  ProxyRig smooth, rough;
  smooth.add(quad({-0.2, -0.2, 0}, {0.2, -0.2, 0}, {0.2, 0.2, 0}, {-0.2, 0.2, 0}), stiff(1000.0));
  rough.add(quad({-0.2, -0.2, 0}, {0.2, -0.2, 0}, {0.2, 0.2, 0}, {-0.2, 0.2, 0}), textured(grating(0.002, 5e-4)));
  for (ProxyRig* rig : {&smooth, &rough}) reset_proxy(rig->state, {0, 0, 0.01});
  for (int i = 1; i <= 600; ++i) {
    const Eigen::Vector3d hip(0.0001 * i, 0.00005 * i, 0.01 - 0.00004 * i);
    const ProxyOutput a = smooth.step(hip);
    const ProxyOutput b = rough.step(hip);
    ASSERT_EQ(a.proxy_W, b.proxy_W) << "tick " << i;
    ASSERT_GE(b.proxy_W.z(), 0.0);
    ASSERT_EQ(a.in_contact, b.in_contact);
  }
}

TEST(TextureForce, ATextureOnAMovedObjectMovesWithIt) {
  // The same plate turned 90 degrees about z with its grating: a stroke along y meets the ridges.
  const HapticMaterial m = textured(grating(0.002, 2e-4));
  ProxyRig rig;
  Pose X_WO = Pose::Identity();
  X_WO.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  rig.add(quad({-0.2, -0.2, 0}, {0.2, -0.2, 0}, {0.2, 0.2, 0}, {-0.2, 0.2, 0}), m, X_WO);
  // Texture u runs along the object's x, which is the world's y now.
  const Eigen::Vector3d p_W(0.0, 0.0005, 0.0);  // a quarter period along u: steepest slope
  const Eigen::Vector3d n_W = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d f = textured_force(rig.world, m, 0, p_W, n_W, Eigen::Vector3d(0, 0, 2.0));
  EXPECT_GT(std::abs(f.y()), 0.1);
  EXPECT_NEAR(f.x(), 0.0, 1e-12);
}

}  // namespace
}  // namespace mhd::test
