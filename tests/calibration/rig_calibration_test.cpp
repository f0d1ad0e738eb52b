// The rig calibration (engine/calibration/rig_calibration.h) on synthetic samples from the
// thesis's rig: recovery of the offsets and psi, the noise floor, what cannot be observed,
// and the refusals for bad sample sets.

#include "calibration/rig_calibration.h"
#include "calibration/sample_synthesis.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <vector>

namespace mhd {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Rig pomhi_rig() {
  const Result<SceneDescription> read = read_scene_file(std::filesystem::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml");
  EXPECT_TRUE(read.ok());
  const Result<Rig, std::vector<RigError>> built = Rig::from_scene(*read);
  EXPECT_TRUE(built.ok());
  return *built;
}

/// c = SR + Rz(psi) R_SR RP: what the samples determine.
Eigen::Vector3d phantom_in_sensor(const Rig& rig, const RigOffsets& o) {
  return calibrated_X_base_sensor_robot(rig, o) * o.p_R_phantom_m;
}

TEST(RigCalibration, RigOffsetsPredictWhatTheRigPredicts) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;
  options.samples = 20;
  const std::vector<CalibrationSample> samples = synthesize_samples(rig, options);
  for (const CalibrationSample& s : samples) {
    const Eigen::Vector3d expected = rig.p_W_hip(rig.X_W_robot_from_sensor(s.X_is900_base_sensor), s.q_rad);
    EXPECT_LT((predicted_p_W_hip(rig, offsets_of(rig), s.X_is900_base_sensor, s.q_rad) - expected).norm(), 1e-12);
  }
}

TEST(RigCalibration, PsiIsAYawAboutTheSensorsVertical) {
  const Rig rig = pomhi_rig();
  RigOffsets o = offsets_of(rig);
  o.psi_rad = 10.0 * kDeg;
  const Pose X_W_S = rig.X_W_is900() * rig.X_is900_base_sensor_nominal();
  const Pose X_W_robot_0 = X_W_S * rig.X_base_sensor_robot();
  const Pose X_W_robot_psi = X_W_S * calibrated_X_base_sensor_robot(rig, o);
  // The robot turns about world up (base_sensor z is up with pomhi.xml): counter-clockwise from above.
  const Eigen::Matrix3d turn = X_W_robot_psi.linear() * X_W_robot_0.linear().transpose();
  const Eigen::AngleAxisd axis_angle(turn);
  EXPECT_NEAR(axis_angle.angle(), 10.0 * kDeg, 1e-12);
  EXPECT_NEAR(axis_angle.axis().dot(Eigen::Vector3d::UnitY()), 1.0, 1e-12);
}

TEST(RigCalibration, NoiseFreeSamplesGiveTheTruthExactly) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;
  options.sensor_noise_m = 0.0;
  options.hip_noise_m = 0.0;
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, synthesize_samples(rig, options));
  ASSERT_TRUE(outcome.ok()) << outcome.error_text();
  const CalibrationFit& r = *outcome;
  EXPECT_LT((r.p_S_phantom_m - phantom_in_sensor(rig, options.truth)).norm(), 1e-9);
  EXPECT_NEAR(r.after.psi_rad, options.truth.psi_rad, 1e-9);
  EXPECT_LT(r.residuals_after.rmse_3d_m, 1e-9);
}

TEST(RigCalibration, LargePsiConvergesFromZero) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;
  options.sensor_noise_m = 0.0;
  options.hip_noise_m = 0.0;
  options.truth.psi_rad = 30.0 * kDeg;
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, synthesize_samples(rig, options));
  ASSERT_TRUE(outcome.ok()) << outcome.error_text();
  EXPECT_NEAR(outcome->after.psi_rad, options.truth.psi_rad, 1e-9);
  EXPECT_LT(outcome->residuals_after.rmse_3d_m, 1e-9);
}

// The acceptance test: thesis-like samples (bases within +-1 m, random heading and
// joint angles) with 2 mm tracker noise on both the station and the HIP marker. psi is seen
// only through the arm's reach (~0.1 m levers), so 100 samples leave it a standard deviation
// of about 0.1 deg (next test); 1000 samples bring that to about 0.03 deg.
TEST(RigCalibration, RecoversOffsetsWithin1mmAndPsiWithinATenthOfADegreeAt2mmNoise) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;  // thesis values, psi 1.5 deg, 2 mm noise, seed 1
  options.samples = 1000;
  const std::vector<CalibrationSample> samples = synthesize_samples(rig, options);
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, samples);
  ASSERT_TRUE(outcome.ok()) << outcome.error_text();
  const CalibrationFit& r = *outcome;

  EXPECT_LT((r.p_S_phantom_m - phantom_in_sensor(rig, options.truth)).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_LT(std::abs(r.after.psi_rad - options.truth.psi_rad), 0.1 * kDeg);
  // The six offsets with the even split: the thesis's values differ from the ruler's
  // mostly along what the data see (the unseen part is 0.65 mm), so they come back within
  // 1 mm too (docs/calibration.md).
  EXPECT_LT((r.after.p_S_robot_m - options.truth.p_S_robot_m).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_LT((r.after.p_R_phantom_m - options.truth.p_R_phantom_m).cwiseAbs().maxCoeff(), 1e-3);

  // Residuals: the noise floor after, tens of millimetres before (the thesis's 0-40 mm).
  const double floor_m = position_noise_floor_m(options);  // 2.83 mm per axis
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_GT(r.residuals_after.rmse_m(axis), 0.9 * floor_m) << axis;
    EXPECT_LT(r.residuals_after.rmse_m(axis), 1.1 * floor_m) << axis;
  }
  EXPECT_GT(r.residuals_before.rmse_m.y(), 0.030);  // SRz + RPz: 35.2 mm off
  EXPECT_GT(r.residuals_before.rmse_m.x(), 0.005);
  // Least squares: never worse than the truth on its own data, and hardly better.
  const ResidualStats at_truth = residual_stats(rig, options.truth, samples);
  EXPECT_LE(r.residuals_after.rmse_3d_m, at_truth.rmse_3d_m);
  EXPECT_GT(r.residuals_after.rmse_3d_m, 0.99 * at_truth.rmse_3d_m);
  EXPECT_LT(r.sigma(kPsi), 0.04 * kDeg);
  EXPECT_LT(std::abs(r.after.psi_rad - options.truth.psi_rad), 4.0 * r.sigma(kPsi));
}

struct SeedStats {
  int count = 0;
  int within = 0;  ///< c within 1 mm and psi within 0.1 deg
  int c_within = 0;
  double sum_sq_psi_error = 0.0, sum_sq_psi_sigma = 0.0;
  double sum_sq_c_error = 0.0, sum_sq_c_sigma = 0.0;  ///< over x, y, z
  double worst_psi_deg = 0.0, worst_c_mm = 0.0;
};

SeedStats run_seeds(const Rig& rig, int samples, int seeds) {
  SeedStats st;
  for (int seed = 1; seed <= seeds; ++seed) {
    SynthesisOptions options;
    options.samples = samples;
    options.seed = static_cast<std::uint64_t>(seed);
    const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, synthesize_samples(rig, options));
    EXPECT_TRUE(outcome.ok()) << seed << ": " << outcome.error_text();
    if (!outcome.ok()) continue;
    const CalibrationFit& r = *outcome;
    const double psi_error = r.after.psi_rad - options.truth.psi_rad;
    const Eigen::Vector3d c_error = r.p_S_phantom_m - phantom_in_sensor(rig, options.truth);
    ++st.count;
    st.sum_sq_psi_error += psi_error * psi_error;
    st.sum_sq_psi_sigma += r.sigma(kPsi) * r.sigma(kPsi);
    st.sum_sq_c_error += c_error.squaredNorm();
    st.sum_sq_c_sigma += r.sigma.head<3>().squaredNorm();
    st.worst_psi_deg = std::max(st.worst_psi_deg, std::abs(psi_error) / kDeg);
    st.worst_c_mm = std::max(st.worst_c_mm, 1e3 * c_error.cwiseAbs().maxCoeff());
    const bool c_ok = c_error.cwiseAbs().maxCoeff() < 1e-3;
    st.c_within += c_ok ? 1 : 0;
    st.within += (c_ok && std::abs(psi_error) < 0.1 * kDeg) ? 1 : 0;
  }
  std::printf("%d samples x %d seeds: within 1 mm and 0.1 deg: %d; c within 1 mm: %d; psi error rms %.4f deg "
              "(reported sigma rms %.4f), worst %.4f deg; c error rms %.4f mm per axis (sigma %.4f), worst %.4f mm\n",
              samples, seeds, st.within, st.c_within, std::sqrt(st.sum_sq_psi_error / st.count) / kDeg,
              std::sqrt(st.sum_sq_psi_sigma / st.count) / kDeg, st.worst_psi_deg,
              1e3 * std::sqrt(st.sum_sq_c_error / (3.0 * st.count)), 1e3 * std::sqrt(st.sum_sq_c_sigma / (3.0 * st.count)),
              st.worst_c_mm);
  return st;
}

// The same over many seeds: how often the tolerances hold (figures in docs/calibration.md).
TEST(RigCalibration, RecoveryHoldsOverManySeedsWith1000Samples) {
  const SeedStats st = run_seeds(pomhi_rig(), 1000, 30);
  EXPECT_GE(st.within, 29) << "worst psi " << st.worst_psi_deg << " deg, worst c " << st.worst_c_mm << " mm";
}

// The thesis's 100 samples: the offset within 1 mm nearly always, psi to about 0.1 deg, and
// the standard deviations the fit reports match the errors it makes.
TEST(RigCalibration, ThesisSizedSetsGiveTheReportedUncertainty) {
  const SeedStats st = run_seeds(pomhi_rig(), 100, 100);
  EXPECT_GE(st.c_within, 97);
  const double psi_ratio = std::sqrt(st.sum_sq_psi_error / st.sum_sq_psi_sigma);
  const double c_ratio = std::sqrt(st.sum_sq_c_error / st.sum_sq_c_sigma);
  EXPECT_GT(psi_ratio, 0.8);
  EXPECT_LT(psi_ratio, 1.25);
  EXPECT_GT(c_ratio, 0.8);
  EXPECT_LT(c_ratio, 1.25);
}

// Moving SR by d and RP by -(Rz(psi) R_SR)^T d leaves every HIP where it was: no sample set
// can tell the two apart (eq. 4.6's columns: SRx = -RPy, SRy = -RPx, SRz = RPz).
TEST(RigCalibration, SplitBetweenSensorAndArmOffsetsIsNotObservable) {
  const Rig rig = pomhi_rig();
  SynthesisOptions a;
  a.sensor_noise_m = 0.0;
  a.hip_noise_m = 0.0;
  SynthesisOptions b = a;
  const Eigen::Vector3d d(0.010, -0.020, 0.030);
  b.truth.p_S_robot_m += d;
  b.truth.p_R_phantom_m -= calibrated_X_base_sensor_robot(rig, b.truth).linear().transpose() * d;
  const std::vector<CalibrationSample> sa = synthesize_samples(rig, a);
  const std::vector<CalibrationSample> sb = synthesize_samples(rig, b);
  ASSERT_EQ(sa.size(), sb.size());
  for (std::size_t i = 0; i < sa.size(); ++i) {
    EXPECT_LT((sa[i].p_W_hip_measured_m - sb[i].p_W_hip_measured_m).norm(), 1e-12);
  }
  // Each split rule fits both equally; they differ only in where they put the change.
  for (const OffsetSplit split : {OffsetSplit::Even, OffsetSplit::HoldSensorToRobot, OffsetSplit::HoldRobotToPhantom}) {
    CalibrationOptions options;
    options.split = split;
    const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, sa, options);
    ASSERT_TRUE(outcome.ok()) << outcome.error_text();
    EXPECT_LT(outcome->residuals_after.rmse_3d_m, 1e-9) << to_string(split);
    EXPECT_LT((phantom_in_sensor(rig, outcome->after) - phantom_in_sensor(rig, a.truth)).norm(), 1e-9);
  }
  CalibrationOptions hold_sr;
  hold_sr.split = OffsetSplit::HoldSensorToRobot;
  EXPECT_EQ(calibrate_rig(rig, sa, hold_sr)->after.p_S_robot_m, offsets_of(rig).p_S_robot_m);
  CalibrationOptions hold_rp;
  hold_rp.split = OffsetSplit::HoldRobotToPhantom;
  EXPECT_EQ(calibrate_rig(rig, sa, hold_rp)->after.p_R_phantom_m, offsets_of(rig).p_R_phantom_m);
}

TEST(RigCalibration, SplitNamesRoundTrip) {
  for (const OffsetSplit split : {OffsetSplit::Even, OffsetSplit::HoldSensorToRobot, OffsetSplit::HoldRobotToPhantom}) {
    EXPECT_EQ(offset_split_from_string(to_string(split)), split);
  }
  EXPECT_FALSE(offset_split_from_string("half").has_value());
}

// The thesis's fit (six offsets, no psi) on a rig with a 1.5 degree yaw: y comes down to the
// noise, x and z do not (its ch. 4.4.3 finding, and why it proposed psi).
TEST(RigCalibration, WithoutPsiXAndZStayAboveTheNoise) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;
  const std::vector<CalibrationSample> samples = synthesize_samples(rig, options);
  CalibrationOptions no_psi;
  no_psi.estimate_psi = false;
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, samples, no_psi);
  ASSERT_TRUE(outcome.ok()) << outcome.error_text();
  const double floor_m = position_noise_floor_m(options);
  EXPECT_LT(outcome->residuals_after.rmse_m.y(), 1.15 * floor_m);
  EXPECT_GT(outcome->residuals_after.rmse_m.x(), 1.5 * floor_m);
  EXPECT_GT(outcome->residuals_after.rmse_m.z(), 1.5 * floor_m);
  EXPECT_EQ(outcome->after.psi_rad, 0.0);
}

// One heading for every sample is enough: the station's pose is measured in full, so the
// offset is seen in all three directions; psi shows through the joint angles.
TEST(RigCalibration, OneHeadingForAllSamplesStillCalibrates) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;
  std::vector<CalibrationSample> samples = synthesize_samples(rig, options);
  const Pose X_is900_S = rig.X_is900_base_sensor_from_base(BasePose{0.3, -0.2, 0.7});
  for (CalibrationSample& s : samples) {
    s.X_is900_base_sensor = X_is900_S;
    s.p_W_hip_measured_m = predicted_p_W_hip(rig, options.truth, X_is900_S, s.q_rad);
  }
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, samples);
  ASSERT_TRUE(outcome.ok()) << outcome.error_text();
  EXPECT_NEAR(outcome->after.psi_rad, options.truth.psi_rad, 1e-9);
}

TEST(RigCalibration, SameJointAnglesLeavePsiUnobservable) {
  const Rig rig = pomhi_rig();
  std::vector<CalibrationSample> samples = synthesize_samples(rig, SynthesisOptions{});
  for (CalibrationSample& s : samples) s.q_rad = Eigen::Vector3d(0.2, 0.3, 0.1);
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, samples);
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.error().kind, CalibrationErrorKind::Unobservable);
  EXPECT_EQ(outcome.error().parameter, "psi");
  const std::string& m = outcome.error().message;
  EXPECT_EQ(m.rfind("the samples leave psi (the robot's yaw about base_sensor z) unobservable: it is confounded with "
                    "phantom_in_sensor_",
                    0),
            0U)
      << m;
  EXPECT_NE(m.find("vary the joint angles"), std::string::npos) << m;
}

TEST(RigCalibration, JointAnglesThatBarelyMoveLeavePsiPoorlyDetermined) {
  const Rig rig = pomhi_rig();
  std::vector<CalibrationSample> samples = synthesize_samples(rig, SynthesisOptions{});
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i].q_rad = Eigen::Vector3d(0.2, 0.3, 0.1) + Eigen::Vector3d::Constant(0.002 * std::sin(static_cast<double>(i)));
  }
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, samples);
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.error().parameter, "psi");
  EXPECT_TRUE(outcome.error().kind == CalibrationErrorKind::PoorlyDetermined ||
              outcome.error().kind == CalibrationErrorKind::Unobservable)
      << outcome.error().message;
}

TEST(RigCalibration, TooFewSamples) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;
  options.samples = 9;
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, synthesize_samples(rig, options));
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.error().kind, CalibrationErrorKind::TooFewSamples);
  EXPECT_EQ(outcome.error().message, "9 samples; calibration needs at least 10");
  EXPECT_EQ(calibrate_rig(rig, {}).error().message, "0 samples; calibration needs at least 10");
}

TEST(RigCalibration, IterationLimitIsReported) {
  const Rig rig = pomhi_rig();
  CalibrationOptions options;
  options.max_iterations = 1;
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, synthesize_samples(rig, SynthesisOptions{}), options);
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.error().kind, CalibrationErrorKind::NotConverged);
  EXPECT_EQ(outcome.error().message, "the fit did not converge in 1 iterations");
}

TEST(RigCalibration, SynthesisIsDeterministicPerSeed) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;
  options.samples = 5;
  const std::vector<CalibrationSample> a = synthesize_samples(rig, options);
  const std::vector<CalibrationSample> b = synthesize_samples(rig, options);
  options.seed = 2;
  const std::vector<CalibrationSample> c = synthesize_samples(rig, options);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].p_W_hip_measured_m, b[i].p_W_hip_measured_m);
    EXPECT_NE(a[i].p_W_hip_measured_m, c[i].p_W_hip_measured_m);
    EXPECT_TRUE(rig.device().limits.contains(a[i].q_rad));
    const BasePose base = rig.base_from_sensor(a[i].X_is900_base_sensor);
    EXPECT_LE(std::abs(base.x_m), 1.0 + 0.01);
    EXPECT_LE(std::abs(base.z_m), 1.0 + 0.01);
  }
}

// With orientation noise on the station as well (IS-900: a few tenths of a degree), the fit
// still lands on the floor that the truth itself leaves.
TEST(RigCalibration, OrientationNoiseRaisesTheFloorNotTheError) {
  const Rig rig = pomhi_rig();
  SynthesisOptions options;
  options.sensor_noise_rad = 0.25 * kDeg;
  const std::vector<CalibrationSample> samples = synthesize_samples(rig, options);
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, samples);
  ASSERT_TRUE(outcome.ok()) << outcome.error_text();
  const ResidualStats at_truth = residual_stats(rig, options.truth, samples);
  EXPECT_LE(outcome->residuals_after.rmse_3d_m, at_truth.rmse_3d_m);
  EXPECT_GT(outcome->residuals_after.rmse_3d_m, 0.95 * at_truth.rmse_3d_m);
  EXPECT_LT((outcome->p_S_phantom_m - phantom_in_sensor(rig, options.truth)).cwiseAbs().maxCoeff(), 2e-3);
  EXPECT_LT(std::abs(outcome->after.psi_rad - options.truth.psi_rad), 0.2 * kDeg);
}

/// pomhi's rig with tall_column.xml's lift: the arm from -0.6 m to +1.0 m about its frame.
Rig lifted_rig() {
  Result<SceneDescription> read = read_scene_file(std::filesystem::path(MHD_SOURCE_DIR) / "scenes/rigs/pomhi.xml");
  EXPECT_TRUE(read.ok());
  LiftDescription lift;
  lift.min_m = -0.6;
  lift.max_m = 1.0;
  lift.max_speed_mps = 0.3;
  lift.max_acceleration_mps2 = 1.0;
  read->rig_lift = lift;
  const Result<Rig, std::vector<RigError>> lifted = Rig::from_scene(*read);
  EXPECT_TRUE(lifted.ok());
  return *lifted;
}

TEST(RigCalibration, ALiftedRigCalibratesWithTheLiftsHeightAndNotWithout) {
  const Rig rig = lifted_rig();
  SynthesisOptions options;
  options.samples = 400;
  std::vector<CalibrationSample> samples = synthesize_samples(rig, options);
  double lowest = 1e9, highest = -1e9;
  for (const CalibrationSample& s : samples) {
    lowest = std::min(lowest, s.lift_m);
    highest = std::max(highest, s.lift_m);
  }
  EXPECT_LT(lowest, -0.4);  // the samples span the lift's range
  EXPECT_GT(highest, 0.8);
  const Result<CalibrationFit, CalibrationError> outcome = calibrate_rig(rig, samples);
  ASSERT_TRUE(outcome.ok()) << outcome.error_text();
  EXPECT_LT((outcome->p_S_phantom_m - phantom_in_sensor(rig, options.truth)).cwiseAbs().maxCoeff(), 1.5e-3);
  EXPECT_LT(std::abs(outcome->after.psi_rad - options.truth.psi_rad), 0.2 * kDeg);
  EXPECT_LT(outcome->residuals_after.rmse_3d_m, 2.0 * std::sqrt(3.0) * position_noise_floor_m(options));
  // The dual: with the lift's height forgotten, not even the true offsets explain the
  // samples, and the fit is refused (or, were it not, would leave the same residuals).
  for (CalibrationSample& s : samples) s.lift_m = 0.0;
  EXPECT_GT(residual_stats(rig, options.truth, samples).rmse_3d_m, 0.2);
  const Result<CalibrationFit, CalibrationError> blind = calibrate_rig(rig, samples);
  if (blind.ok()) {
    EXPECT_GT(blind->residuals_after.rmse_3d_m, 0.2);
  } else {
    EXPECT_EQ(blind.error().kind, CalibrationErrorKind::PoorlyDetermined) << blind.error_text();
  }
}

TEST(RigCalibration, ALiftHeightTheRigCannotHaveIsRefusedAtItsLine) {
  std::vector<CalibrationSample> samples(3);
  for (int i = 0; i < 3; ++i) samples[static_cast<std::size_t>(i)].line = 10 + i;
  samples[1].lift_m = 0.25;
  samples[2].lift_m = 1.2;
  // A rig without a lift: any height but 0 is refused.
  const Diagnostics none = lift_problems(pomhi_rig(), samples, "s.csv");
  ASSERT_EQ(none.size(), 2u);
  EXPECT_EQ(none[0].to_string(), "s.csv:11: error: lift_m 0.25 m, but the rig has no lift (<rig><lift>)");
  // With a lift of [-0.6, 1.0] m: 1.2 m is out of range, 0.25 m is not.
  const Diagnostics lifted = lift_problems(lifted_rig(), samples, "s.csv");
  ASSERT_EQ(lifted.size(), 1u);
  EXPECT_EQ(lifted[0].to_string(), "s.csv:12: error: lift_m 1.2 m is outside the lift's range [-0.6, 1] m");
  samples[2].lift_m = 1.0005;  // within a reading's error of the top
  EXPECT_TRUE(lift_problems(lifted_rig(), samples, "s.csv").empty());
}

}  // namespace
}  // namespace mhd
