#include "calibration/calibration_report.h"
#include "calibration/text_concat.h"

#include <array>
#include <cstdio>
#include <numbers>

namespace mhd {

namespace {

using calibration_detail::kDegPerRad;

std::string line_of(const char* text) { return std::string(text); }

std::string mm(const Eigen::Vector3d& v_m) {
  std::array<char, 96> b{};
  std::snprintf(b.data(), b.size(), "(%.2f, %.2f, %.2f)", v_m.x() * 1e3, v_m.y() * 1e3, v_m.z() * 1e3);
  return std::string(b.data());
}

std::string rmse_row(const char* label, const ResidualStats& s) {
  std::array<char, 128> b{};
  std::snprintf(b.data(), b.size(), "  %-8s %9.2f %9.2f %9.2f %9.2f\n", label, s.rmse_m.x() * 1e3, s.rmse_m.y() * 1e3,
                s.rmse_m.z() * 1e3, s.rmse_3d_m * 1e3);
  return std::string(b.data());
}

std::string split_text(OffsetSplit split) {
  switch (split) {
    case OffsetSplit::Even: return "even (the least change of SR and RP from the rig's values)";
    case OffsetSplit::HoldSensorToRobot: return "hold-sr (SR kept, RP moved)";
    case OffsetSplit::HoldRobotToPhantom: return "hold-rp (RP kept, SR moved)";
  }
  return "";
}

}  // namespace

std::string format_calibration_report(const CalibrationFit& r, OffsetSplit split) {
  std::string out = line_of("residual RMSE (mm)        x         y         z       3-D\n");
  out += rmse_row("before", r.residuals_before);
  out += rmse_row("after", r.residuals_after);
  std::array<char, 512> b{};
  std::snprintf(b.data(), b.size(), "psi (robot yaw about base_sensor z): %.4f deg +- %.4f\n", r.after.psi_rad * kDegPerRad,
                r.sigma(kPsi) * kDegPerRad);
  out += b.data();
  std::snprintf(b.data(), b.size(), "PHANToM origin in base_sensor (SR + R RP), mm: %s -> %s +- (%.2f, %.2f, %.2f)\n",
                mm(r.p_S_phantom_before_m).c_str(), mm(r.p_S_phantom_m).c_str(), r.sigma(0) * 1e3, r.sigma(1) * 1e3,
                r.sigma(2) * 1e3);
  out += b.data();
  out += "SR base_sensor -> robot, mm: " + mm(r.before.p_S_robot_m) + " -> " + mm(r.after.p_S_robot_m) + "\n";
  out += "RP robot -> phantom, mm:     " + mm(r.before.p_R_phantom_m) + " -> " + mm(r.after.p_R_phantom_m) + "\n";
  out += "note: the samples fix SR + R RP and psi, not SR and RP apart; split: " + split_text(split) + "\n";
  return out;
}

std::string format_residuals_csv(const Rig& rig, const std::vector<CalibrationSample>& samples,
                                 const CalibrationFit& result) {
  std::string out(kResidualsHeader);
  out += "\n";
  std::array<char, 512> b{};
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const BasePose base = rig.base_from_sensor(samples[i].X_is900_base_sensor);
    const Eigen::Vector3d& before = result.residuals_before.residuals_m[i];
    const Eigen::Vector3d& after = result.residuals_after.residuals_m[i];
    std::snprintf(b.data(), b.size(), "%d,%.6f,%.6f,%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", samples[i].line, base.x_m,
                  base.z_m, base.heading_rad, before.x(), before.y(), before.z(), after.x(), after.y(), after.z());
    out += b.data();
  }
  return out;
}

std::vector<std::string> calibration_note_lines(const CalibrationFit& r, const std::string& samples_file,
                                                OffsetSplit split) {
  std::array<char, 256> b{};
  std::vector<std::string> lines;
  lines.push_back(std::to_string(r.residuals_after.residuals_m.size()) + " samples from " + samples_file + ";");
  std::snprintf(b.data(), b.size(), "psi = %.4f deg (robot yaw about base_sensor z, +- %.4f);",
                r.after.psi_rad * kDegPerRad, r.sigma(kPsi) * kDegPerRad);
  lines.emplace_back(b.data());
  lines.push_back("SR " + mm(r.before.p_S_robot_m) + " -> " + mm(r.after.p_S_robot_m) + " mm, RP " +
                  mm(r.before.p_R_phantom_m) + " -> " + mm(r.after.p_R_phantom_m) + " mm,");
  lines.push_back("split " + std::string(to_string(split)) + " (the samples fix SR + R RP, not SR and RP apart);");
  std::snprintf(b.data(), b.size(), "base height follows SRz; residual RMSE x y z: %.2f %.2f %.2f -> %.2f %.2f %.2f mm.",
                r.residuals_before.rmse_m.x() * 1e3, r.residuals_before.rmse_m.y() * 1e3,
                r.residuals_before.rmse_m.z() * 1e3, r.residuals_after.rmse_m.x() * 1e3,
                r.residuals_after.rmse_m.y() * 1e3, r.residuals_after.rmse_m.z() * 1e3);
  lines.emplace_back(b.data());
  return lines;
}

}  // namespace mhd
