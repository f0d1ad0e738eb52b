#include "calibration/rig_calibration.h"
#include "calibration/text_concat.h"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mhd {

namespace {

using calibration_detail::concat;
using calibration_detail::kDegPerRad;

/// "%.3g" of a value.
std::string g3(double value) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.3g", value);
  return std::string(buffer.data());
}

Eigen::Matrix3d yaw_about_z(double psi_rad) {
  return Eigen::AngleAxisd(psi_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

constexpr std::array<std::string_view, 4> kParameterNames = {"phantom_in_sensor_x", "phantom_in_sensor_y",
                                                             "phantom_in_sensor_z", "psi"};

std::string describe_parameter(int k) {
  if (k == kPsi) return "psi (the robot's yaw about base_sensor z)";
  return concat(kParameterNames[static_cast<std::size_t>(k)],
                " (the PHANToM origin in base_sensor, SR + R RP, along its ", std::string(1, static_cast<char>('x' + k)),
                ")");
}

/// The fit's state: c (the PHANToM origin in base_sensor) and psi.
struct FitState {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  double psi_rad = 0.0;
};

/// Normal equations of the fit, accumulated per sample (fixed size: nothing grows with N).
/// With n = 3 parameters (psi held), only the top-left blocks are used.
struct NormalEquations {
  Eigen::Matrix4d JtJ = Eigen::Matrix4d::Zero();
  Eigen::Vector4d Jtr = Eigen::Vector4d::Zero();
  double cost = 0.0;  ///< sum of squared residuals
};

class Problem {
 public:
  Problem(const Rig& rig, const std::vector<CalibrationSample>& samples)
      : A_(rig.X_base_sensor_robot().linear() * rig.X_robot_phantom().linear()) {
    terms_.reserve(samples.size());
    // The lift raises the arm along the robot's z: in base_sensor, before psi, R_SR z lift.
    const Eigen::Vector3d lift_axis_S = rig.X_base_sensor_robot().linear() * Eigen::Vector3d::UnitZ();
    for (const CalibrationSample& s : samples) {
      const Pose X_W_S = rig.X_W_is900() * s.X_is900_base_sensor;
      terms_.push_back({X_W_S.linear(), X_W_S.translation(),
                        A_ * phantom_tool_position(rig.device().geometry, s.q_rad) + lift_axis_S * s.lift_m,
                        s.p_W_hip_measured_m});
    }
  }

  [[nodiscard]] std::size_t size() const { return terms_.size(); }

  /// Residuals are measured - predicted; J is d prediction / d (c, psi).
  [[nodiscard]] NormalEquations evaluate(const FitState& x) const {
    NormalEquations out;
    const Eigen::Matrix3d R_psi = yaw_about_z(x.psi_rad);
    for (const Term& t : terms_) {
      const Eigen::Vector3d v_S = R_psi * t.a_S;
      const Eigen::Vector3d r = t.p_W_measured - (t.R_W_S * (x.c + v_S) + t.p_W_S);
      Eigen::Matrix<double, 3, 4> J;
      J.leftCols<3>() = t.R_W_S;
      J.col(kPsi) = t.R_W_S * Eigen::Vector3d::UnitZ().cross(v_S);
      out.JtJ.noalias() += J.transpose() * J;
      out.Jtr.noalias() += J.transpose() * r;
      out.cost += r.squaredNorm();
    }
    return out;
  }

 private:
  /// Per sample, what does not change during the fit.
  struct Term {
    Eigen::Matrix3d R_W_S;
    Eigen::Vector3d p_W_S;
    Eigen::Vector3d a_S;  ///< R_SR (R_RP p_P_tool + z lift): the arm's reach in base_sensor before psi
    Eigen::Vector3d p_W_measured;
  };
  Eigen::Matrix3d A_;
  std::vector<Term> terms_;
};

struct Conditioning {
  double condition_number = 0.0;
  Eigen::Vector4d weakest_direction = Eigen::Vector4d::Zero();  ///< in column-scaled parameters
  int zero_column = -1;  ///< a parameter that moves nothing
  int count = 4;
};

/// Condition number of the column-scaled Jacobian, from its normal matrix (cond(J)^2).
Conditioning conditioning_of(const Eigen::Matrix4d& JtJ, int n) {
  Conditioning out;
  out.count = n;
  const Eigen::Vector4d norms = JtJ.diagonal().cwiseMax(0.0).cwiseSqrt();
  double largest = 0.0;
  for (int k = 0; k < n; ++k) largest = std::max(largest, norms(k));
  for (int k = 0; k < n; ++k) {
    if (norms(k) <= 1e-12 * std::max(largest, 1e-300)) {
      out.zero_column = k;
      out.condition_number = std::numeric_limits<double>::infinity();
      return out;
    }
  }
  Eigen::Matrix4d scaled = Eigen::Matrix4d::Identity();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) scaled(i, j) = JtJ(i, j) / (norms(i) * norms(j));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(scaled);
  // With n = 3 the padding adds an eigenvalue of 1, between the others (they sum to 3).
  const Eigen::Vector4d& lambda = eigen.eigenvalues();  // ascending
  const double smallest = std::max(lambda(0), 0.0);
  out.condition_number = smallest > 0.0 ? std::sqrt(lambda(3) / smallest) : std::numeric_limits<double>::infinity();
  out.weakest_direction = eigen.eigenvectors().col(0);
  return out;
}

CalibrationError unobservable_error(const Conditioning& c, double max_condition) {
  int worst = c.zero_column;
  std::vector<int> partners;
  if (worst < 0) {
    worst = 0;
    for (int k = 1; k < c.count; ++k) {
      if (std::abs(c.weakest_direction(k)) > std::abs(c.weakest_direction(worst))) worst = k;
    }
    for (Eigen::Index k = 0; k < c.count; ++k) {
      if (static_cast<int>(k) != worst && std::abs(c.weakest_direction(k)) > 0.2) partners.push_back(static_cast<int>(k));
    }
  }
  std::string message = concat("the samples leave ", describe_parameter(worst), " unobservable");
  if (c.zero_column >= 0) {
    message += ": it moves no predicted HIP";
  } else {
    message += ": it is confounded with ";
    for (std::size_t i = 0; i < partners.size(); ++i) {
      if (i > 0) message += " and ";
      message += kParameterNames[static_cast<std::size_t>(partners[i])];
    }
    message += concat(" (condition number ", g3(c.condition_number), " > ", g3(max_condition), ")");
  }
  if (worst == kPsi) {
    message += "; psi shows only where the HIP moves horizontally in the device between samples: vary the joint angles";
  }
  return {CalibrationErrorKind::Unobservable, std::string(kParameterNames[static_cast<std::size_t>(worst)]), message};
}

}  // namespace

Diagnostics lift_problems(const Rig& rig, const std::vector<CalibrationSample>& samples, const std::string& file) {
  constexpr double kReadingTolerance_m = 0.001;
  Diagnostics out;
  for (const CalibrationSample& s : samples) {
    const SourceLocation where{file, s.line};
    if (!rig.lift()) {
      if (s.lift_m != 0.0) {
        out.push_back({where, concat("lift_m ", g3(s.lift_m), " m, but the rig has no lift (<rig><lift>)")});
      }
    } else if (s.lift_m < rig.lift()->min_m - kReadingTolerance_m || s.lift_m > rig.lift()->max_m + kReadingTolerance_m) {
      out.push_back({where, concat("lift_m ", g3(s.lift_m), " m is outside the lift's range [", g3(rig.lift()->min_m),
                                   ", ", g3(rig.lift()->max_m), "] m")});
    }
  }
  return out;
}

RigOffsets offsets_of(const Rig& rig) noexcept {
  RigOffsets o;
  o.p_S_robot_m = rig.X_base_sensor_robot().translation();
  o.p_R_phantom_m = rig.X_robot_phantom().translation();
  o.psi_rad = 0.0;
  return o;
}

RigOffsets thesis_calibrated_offsets() noexcept {
  RigOffsets o;
  o.p_S_robot_m = Eigen::Vector3d(203.1, -1.8, -387.6) * 1e-3;
  o.p_R_phantom_m = Eigen::Vector3d(-2.1, -232.8, 41.6) * 1e-3;
  o.psi_rad = 1.5 / kDegPerRad;
  return o;
}

Pose calibrated_X_base_sensor_robot(const Rig& rig, const RigOffsets& offsets) noexcept {
  Pose X = rig.X_base_sensor_robot();
  X.linear() = yaw_about_z(offsets.psi_rad) * rig.X_base_sensor_robot().linear();
  X.translation() = offsets.p_S_robot_m;
  return X;
}

Pose calibrated_X_robot_phantom(const Rig& rig, const RigOffsets& offsets) noexcept {
  Pose X = rig.X_robot_phantom();
  X.translation() = offsets.p_R_phantom_m;
  return X;
}

Eigen::Vector3d predicted_p_W_hip(const Rig& rig, const RigOffsets& offsets, const Pose& X_is900_base_sensor,
                                  const Eigen::Vector3d& q_rad, double lift_m) noexcept {
  Pose X_robot_phantom = calibrated_X_robot_phantom(rig, offsets);
  X_robot_phantom.translation() += lift_m * Eigen::Vector3d::UnitZ();  // the lift: along the robot's z
  const Pose X_W_phantom =
      rig.X_W_is900() * X_is900_base_sensor * calibrated_X_base_sensor_robot(rig, offsets) * X_robot_phantom;
  return X_W_phantom * phantom_tool_position(rig.device().geometry, q_rad);
}

ResidualStats residual_stats(const Rig& rig, const RigOffsets& offsets, const std::vector<CalibrationSample>& samples) {
  ResidualStats stats;
  stats.residuals_m.reserve(samples.size());
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();
  for (const CalibrationSample& s : samples) {
    const Eigen::Vector3d r =
        s.p_W_hip_measured_m - predicted_p_W_hip(rig, offsets, s.X_is900_base_sensor, s.q_rad, s.lift_m);
    stats.residuals_m.push_back(r);
    sum_sq += r.cwiseAbs2();
    stats.max_abs_m = stats.max_abs_m.cwiseMax(r.cwiseAbs());
  }
  if (!samples.empty()) {
    const double n = static_cast<double>(samples.size());
    stats.rmse_m = (sum_sq / n).cwiseSqrt();
    stats.rmse_3d_m = std::sqrt(sum_sq.sum() / n);
  }
  return stats;
}

std::optional<OffsetSplit> offset_split_from_string(std::string_view name) noexcept {
  if (name == "even") return OffsetSplit::Even;
  if (name == "hold-sr") return OffsetSplit::HoldSensorToRobot;
  if (name == "hold-rp") return OffsetSplit::HoldRobotToPhantom;
  return std::nullopt;
}

std::string_view to_string(OffsetSplit split) noexcept {
  switch (split) {
    case OffsetSplit::Even: return "even";
    case OffsetSplit::HoldSensorToRobot: return "hold-sr";
    case OffsetSplit::HoldRobotToPhantom: return "hold-rp";
  }
  return "even";
}

RigOffsets split_offsets(const Rig& rig, const RigOffsets& start, const Eigen::Vector3d& p_S_phantom_m, double psi_rad,
                         OffsetSplit split) noexcept {
  // c = SR + M RP with M = Rz(psi) R_SR; the change e of c is shared by SR and RP.
  const Eigen::Matrix3d M = yaw_about_z(psi_rad) * rig.X_base_sensor_robot().linear();
  const Eigen::Vector3d e = p_S_phantom_m - (start.p_S_robot_m + M * start.p_R_phantom_m);
  RigOffsets out = start;
  out.psi_rad = psi_rad;
  switch (split) {
    case OffsetSplit::Even:  // min |dSR|^2 + |dRP|^2 subject to dSR + M dRP = e
      out.p_S_robot_m += 0.5 * e;
      out.p_R_phantom_m += 0.5 * M.transpose() * e;
      break;
    case OffsetSplit::HoldSensorToRobot: out.p_R_phantom_m += M.transpose() * e; break;
    case OffsetSplit::HoldRobotToPhantom: out.p_S_robot_m += e; break;
  }
  return out;
}

Result<CalibrationFit, CalibrationError> calibrate_rig(const Rig& rig, const std::vector<CalibrationSample>& samples,
                                                       const CalibrationOptions& options) {
  const auto fail = [](CalibrationErrorKind kind, std::string parameter, std::string message) {
    return CalibrationError{kind, std::move(parameter), std::move(message)};
  };
  if (static_cast<int>(samples.size()) < options.min_samples) {
    return fail(CalibrationErrorKind::TooFewSamples, "",
                concat(std::to_string(samples.size()), " sample", samples.size() == 1 ? "" : "s",
                       "; calibration needs at least ", std::to_string(options.min_samples)));
  }

  const int n = options.estimate_psi ? 4 : 3;
  const Problem problem(rig, samples);
  const RigOffsets before = offsets_of(rig);
  FitState x;
  x.c = before.p_S_robot_m + rig.X_base_sensor_robot().linear() * before.p_R_phantom_m;
  const Eigen::Vector3d c_before = x.c;

  NormalEquations normal = problem.evaluate(x);
  const Conditioning start = conditioning_of(normal.JtJ, n);
  if (start.zero_column >= 0 || start.condition_number > options.max_condition) {
    const CalibrationError e = unobservable_error(start, options.max_condition);
    return fail(e.kind, e.parameter, e.message);
  }

  // Levenberg-Marquardt (Marquardt's diagonal scaling); linear in c, mildly nonlinear in psi.
  double lambda = 1e-3;
  int iteration = 0;
  bool converged = false;
  for (; iteration < options.max_iterations && !converged; ++iteration) {
    bool accepted = false;
    while (!accepted && lambda < 1e12) {
      Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
      H.topLeftCorner(n, n) = normal.JtJ.topLeftCorner(n, n);
      H.diagonal().head(n) += lambda * normal.JtJ.diagonal().head(n);
      Eigen::Vector4d g = Eigen::Vector4d::Zero();
      g.head(n) = normal.Jtr.head(n);
      const Eigen::Vector4d step = H.ldlt().solve(g);
      FitState next = x;
      next.c += step.head<3>();
      next.psi_rad += step(kPsi);
      const NormalEquations next_normal = problem.evaluate(next);
      if (next_normal.cost <= normal.cost) {
        const bool tiny_step = step.head<3>().norm() < 1e-12 && std::abs(step(kPsi)) < 1e-12;
        converged = tiny_step || (normal.cost - next_normal.cost) <= 1e-14 * std::max(normal.cost, 1e-300);
        x = next;
        normal = next_normal;
        lambda = std::max(lambda * 0.1, 1e-12);
        accepted = true;
      } else {
        lambda *= 10.0;
      }
    }
    if (!accepted) converged = true;  // no step lowers the cost: at the minimum to rounding
  }
  if (!converged) {
    return fail(CalibrationErrorKind::NotConverged, "",
                concat("the fit did not converge in ", std::to_string(options.max_iterations), " iterations"));
  }

  CalibrationFit result;
  result.iterations = iteration;
  result.condition_number = conditioning_of(normal.JtJ, n).condition_number;

  const double dof = 3.0 * static_cast<double>(problem.size()) - n;
  const double variance = dof > 0.0 ? normal.cost / dof : 0.0;
  Eigen::Matrix4d padded = Eigen::Matrix4d::Identity();
  padded.topLeftCorner(n, n) = normal.JtJ.topLeftCorner(n, n);
  const Eigen::Matrix4d covariance = variance * padded.inverse();
  result.sigma = covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  if (n == 3) result.sigma(kPsi) = 0.0;
  const double residual_rms_mm = std::sqrt(variance) * 1e3;
  if (options.estimate_psi && result.sigma(kPsi) > options.max_psi_sigma_rad) {
    return fail(CalibrationErrorKind::PoorlyDetermined, "psi",
                concat("psi (the robot's yaw about base_sensor z) is poorly determined: standard deviation ",
                       g3(result.sigma(kPsi) * kDegPerRad), " deg (limit ",
                       g3(options.max_psi_sigma_rad * kDegPerRad), " deg) at a residual of ",
                       g3(residual_rms_mm),
                       " mm per axis; take more samples with more varied joint angles"));
  }
  for (int k = 0; k < 3; ++k) {
    if (result.sigma(k) > options.max_offset_sigma_m) {
      return fail(CalibrationErrorKind::PoorlyDetermined, std::string(kParameterNames[static_cast<std::size_t>(k)]),
                  concat(describe_parameter(k), " is poorly determined: standard deviation ",
                         g3(result.sigma(k) * 1e3), " mm (limit ",
                         g3(options.max_offset_sigma_m * 1e3), " mm) at a residual of ",
                         g3(residual_rms_mm), " mm per axis; take more samples"));
    }
  }

  result.before = before;
  result.p_S_phantom_before_m = c_before;
  result.p_S_phantom_m = x.c;
  result.after = split_offsets(rig, before, x.c, x.psi_rad, options.split);
  result.residuals_before = residual_stats(rig, result.before, samples);
  result.residuals_after = residual_stats(rig, result.after, samples);
  return result;
}

}  // namespace mhd
