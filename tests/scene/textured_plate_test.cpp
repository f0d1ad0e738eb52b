// scenes/textured_plate.xml: the grating plate's period is in the force of a stroke over
// it, and textures change no move of the proxy, judged by the exact oracle over fast
// random strokes into all three textured plates and over their edges.

#include "support/scene_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace mhd::test {
namespace {

constexpr double kRate_Hz = 1000.0;
constexpr double kTop_m = 1.010;  // the plates' top faces (y), from the scene's comment

class TexturedPlate : public SceneFixture {};

/// Amplitude of the DFT of `x` (mean removed) at bin k.
double amplitude_at(const std::vector<double>& x, std::size_t k) {
  const double n = static_cast<double>(x.size());
  double mean = 0.0;
  for (double v : x) mean += v / n;
  std::complex<double> sum = 0.0;
  for (std::size_t t = 0; t < x.size(); ++t) {
    sum += (x[t] - mean) * std::polar(1.0, -2.0 * std::numbers::pi * static_cast<double>(k * t) / n);
  }
  return 2.0 * std::abs(sum) / n;
}

TEST_F(TexturedPlate, AStrokeOverTheGratingCarriesItsPeriodAndTheSmoothedPlateDoesNot) {
  ASSERT_NO_FATAL_FAILURE(load("scenes/textured_plate.xml"));
  const int plate = object("grating_plate");
  ASSERT_NE(scene().materials[static_cast<std::size_t>(plate)].texture, nullptr);
  const double period_m = scene().materials[static_cast<std::size_t>(plate)].texture->spec().period_m;
  const Eigen::Vector3d centre_W = scene().world.pose(plate).translation();

  // 2 mm deep, then 1,200 ticks along +x (the grating's direction) at 5 cm/s.
  const double speed_m_per_s = 0.05;
  std::vector<Eigen::Vector3d> path;
  const Eigen::Vector3d above(centre_W.x() - 0.05, kTop_m + 0.01, centre_W.z() + 0.013);
  const Eigen::Vector3d pressed(above.x(), kTop_m - 0.002, above.z());
  for (int i = 0; i <= 100; ++i) path.push_back(above + (pressed - above) * (i / 100.0));
  for (int i = 1; i <= 1200; ++i) path.push_back(pressed + Eigen::Vector3d(speed_m_per_s / kRate_Hz * i, 0, 0));

  const auto stroke_forces = [&] {
    const TickRecord record = drive(path, kRate_Hz);
    std::vector<double> tangential_N;
    for (std::size_t i = record.size() - 1000; i < record.size(); ++i) {
      EXPECT_TRUE(record[i].in_contact);
      tangential_N.push_back(record[i].force_W.x());
    }
    return tangential_N;
  };
  const std::vector<double> textured = stroke_forces();
  scene().materials[static_cast<std::size_t>(plate)].texture = nullptr;
  const std::vector<double> smooth = stroke_forces();

  // 1,000 ticks at 1 kHz: bins 1 Hz apart. The grating's bin must be the spectrum's peak.
  const std::size_t expected = static_cast<std::size_t>(std::lround(speed_m_per_s / period_m));
  std::size_t peak = 1;
  for (std::size_t k = 1; k <= 500; ++k) {
    if (amplitude_at(textured, k) > amplitude_at(textured, peak)) peak = k;
  }
  EXPECT_LE(std::abs(static_cast<double>(peak) - static_cast<double>(expected)), 1.0) << "peak at " << peak << " Hz";
  EXPECT_LT(amplitude_at(smooth, expected), 0.01 * amplitude_at(textured, expected));
}

TEST_F(TexturedPlate, FastStrokesIntoTheTexturedPlatesNeverCross) {
  ASSERT_NO_FATAL_FAILURE(load("scenes/textured_plate.xml"));
  // Anchors on the top faces of the three textured plates (x in [-0.315, 0.155]) and
  // past their edges; speeds up to 1 m/s, grazing to steep, up to 20 mm deep.
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double limit_N = scene().proxy.max_force_N;
  std::size_t crossings = 0, inside = 0, textured_contacts = 0;
  for (int k = 0; k < 600; ++k) {
    const Eigen::Vector3d anchor(-0.32 + 0.48 * u(rng), kTop_m, -0.58 + 0.16 * u(rng));
    const double heading = 2 * std::numbers::pi * u(rng);
    const double grazing = 0.03 + (std::numbers::pi / 2 - 0.03) * u(rng);
    const Eigen::Vector3d d(std::cos(grazing) * std::cos(heading), -std::sin(grazing),
                            std::cos(grazing) * std::sin(heading));
    const Eigen::Vector3d start = anchor - d * (0.005 + 0.025 * u(rng));
    const Eigen::Vector3d end = anchor + d * (0.001 + 0.019 * u(rng));
    const std::vector<Eigen::Vector3d> corners = {start, end, start};
    const TickRecord record = drive(sample_polyline(corners, 0.05 + 0.95 * u(rng), kRate_Hz), kRate_Hz);
    for (const auto& crossing : find_crossings(record)) {
      if (++crossings <= 3) ADD_FAILURE() << "stroke " << k << ": crossing at tick " << crossing.tick;
    }
    inside += count_ticks_inside(record);
    for (const TickSample& tick : record) {
      ASSERT_TRUE(tick.force_W.allFinite());
      ASSERT_LE(tick.force_W.norm(), limit_N * (1 + 1e-12));
      if (tick.in_contact && tick.proxy_W.x() < 0.155 && tick.proxy_W.y() > kTop_m - 1e-3) ++textured_contacts;
    }
  }
  EXPECT_EQ(crossings, 0U);
  EXPECT_EQ(inside, 0U);
  EXPECT_GT(textured_contacts, 5000U);  // the strokes really rub the textures
}

}  // namespace
}  // namespace mhd::test
