// The impedance hand alone: pushed by a constant force it settles at F / k from its
// intended position; with no force it tracks a moving intended path; its free response
// has the mass-spring-damper's frequency and decay.
#include "simulation/hand_impedance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mhd::simulation {
namespace {

using V = Eigen::Vector3d;

TEST(HandImpedance, AConstantForceSettlesTheHandAtForceOverStiffness) {
  const HandImpedanceParams params;  // the literature defaults
  HandImpedance hand(params);
  const V intended(0.1, 1.0, -0.4);
  hand.reset(intended);
  const V F_N(2.0, -3.0, 1.0);
  for (int i = 0; i < 5000; ++i) hand.advance(1e-3, intended, F_N);  // 5 s: many time constants m / b
  const V expected = intended + F_N / params.stiffness_N_per_m;
  EXPECT_LT((hand.p_W_m() - expected).norm(), 1e-6) << hand.p_W_m().transpose();
  EXPECT_LT(hand.v_W_mps().norm(), 1e-6);
  EXPECT_LT((hand.equilibrium_W_m(F_N) - expected).norm(), 1e-12);
  // 3.7 N on 135 N/m: 27 mm, not the stiff spring's 2 mm.
  EXPECT_NEAR((hand.p_W_m() - intended).norm(), F_N.norm() / 135.0, 1e-6);
}

TEST(HandImpedance, WithNoForceTheHandTracksTheIntendedPath) {
  HandImpedance hand(HandImpedanceParams{});
  const V start(0.0, 1.0, 0.0);
  hand.reset(start);
  // A stroke: 3 cm at 0.4 Hz along x, on a walk at 0.3 m/s along -z, sampled at 1 kHz.
  auto intended = [&](double t_s) {
    return V(start.x() + 0.03 * std::sin(2.0 * std::numbers::pi * 0.4 * t_s), start.y(), start.z() - 0.3 * t_s);
  };
  double worst_m = 0.0;
  for (int i = 1; i <= 4000; ++i) {
    const double t_s = 1e-3 * i;
    hand.advance(1e-3, intended(t_s), V::Zero());
    if (t_s > 1.0) worst_m = std::max(worst_m, (hand.p_W_m() - intended(t_s)).norm());
  }
  // The intended velocity is fed forward: the hand lags its path by about a millimetre.
  EXPECT_LT(worst_m, 2e-3);
  EXPECT_NEAR(hand.v_W_intended_mps().z(), -0.3, 0.01);
}

TEST(HandImpedance, TheFreeResponseHasTheMassSpringDamperFrequencyAndDecay) {
  const HandImpedanceParams params;
  HandImpedance hand(params);
  hand.reset(V::Zero());
  // Held at rest 10 mm up by 1.35 N (a step past max_step_s settles it), then let go.
  const double x0_m = 0.01;
  hand.advance(1.0, V::Zero(), V(0.0, x0_m * params.stiffness_N_per_m, 0.0));
  ASSERT_NEAR(hand.p_W_m().y(), x0_m, 1e-12);
  double next_peak_t_s = -1.0, next_peak_m = 0.0;
  double previous_v = 0.0;
  for (int i = 1; i <= 10000 && next_peak_t_s < 0.0; ++i) {
    hand.advance(1e-4, V::Zero(), V::Zero());
    const double v = hand.v_W_mps().y();
    if (i > 1 && previous_v > 0.0 && v <= 0.0) {  // a maximum, one damped period after the start
      next_peak_t_s = 1e-4 * i;
      next_peak_m = hand.p_W_m().y();
    }
    previous_v = v;
  }
  ASSERT_GT(next_peak_t_s, 0.0);
  const double m = params.mass_kg, k = params.stiffness_N_per_m, b = params.damping_Ns_per_m;
  const double sigma = b / (2.0 * m);
  const double period_s = 2.0 * std::numbers::pi / std::sqrt(k / m - sigma * sigma);
  EXPECT_NEAR(next_peak_t_s, period_s, 2e-4);
  EXPECT_NEAR(next_peak_m / x0_m, std::exp(-sigma * period_s), 0.002);
}

TEST(HandImpedance, AStepLongerThanTheLimitRestartsTheHandInEquilibrium) {
  HandImpedanceParams params;
  HandImpedance hand(params);
  hand.reset(V::Zero());
  hand.advance(0.5, V(0.1, 0.0, 0.0), V(0.0, 1.35, 0.0));
  EXPECT_LT((hand.p_W_m() - V(0.1, 0.01, 0.0)).norm(), 1e-12);
  EXPECT_EQ(hand.v_W_mps(), V::Zero());
}

TEST(HandImpedance, AnIntendedHandPlacedFarAwayMovesTheHandThereAtRest) {
  HandImpedance hand(HandImpedanceParams{});
  hand.reset(V::Zero());  // the world's hand before the user first writes it
  hand.advance(1e-3, V(0.4, 1.0, -0.3), V::Zero());
  EXPECT_EQ(hand.p_W_m(), V(0.4, 1.0, -0.3));
  EXPECT_EQ(hand.v_W_mps(), V::Zero());
  EXPECT_EQ(hand.v_W_intended_mps(), V::Zero());
  // A move within reach of one step is a move: the mass lags it.
  hand.advance(1e-3, V(0.45, 1.0, -0.3), V::Zero());
  EXPECT_LT(hand.p_W_m().x(), 0.401);
}

TEST(HandImpedance, RejectsNonPositiveParametersByName) {
  HandImpedanceParams params;
  params.damping_Ns_per_m = 0.0;
  try {
    HandImpedance hand(params);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "hand damping_Ns_per_m must be a positive number");
  }
  params = HandImpedanceParams{};
  params.mass_kg = std::nan("");
  EXPECT_THROW(HandImpedance{params}, std::invalid_argument);
}

}  // namespace
}  // namespace mhd::simulation
