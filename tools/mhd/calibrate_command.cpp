#include "calibrate_command.h"

#include "calibration/calibration_report.h"
#include "calibration/calibration_sample.h"
#include "calibration/rig_calibration.h"
#include "calibration/rig_xml_writer.h"
#include "calibration/sample_synthesis.h"
#include "command_exit.h"
#include "scene_xml/scene_reader.h"

#include <fmt/core.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

struct CalibrateOptions {
  std::string samples;
  std::string rig;
  std::string output;
  std::string residuals;
  std::string split = "even";
  bool no_psi = false;
  bool synthesize = false;
  int count = 100;
  std::uint64_t seed = 1;
  double half_range_m = 1.0;
  double noise_mm = 2.0;
  double angle_noise_deg = 0.0;
  double psi_deg = 1.5;
  std::vector<double> sr_mm = {203.1, -1.8, -387.6};
  std::vector<double> rp_mm = {-2.1, -232.8, 41.6};
};

void print_error(const std::string& where, int line, const std::string& message) {
  if (where.empty()) {
    fmt::print(stderr, "mhd calibrate: error: {}\n", message);
  } else if (line > 0) {
    fmt::print(stderr, "mhd calibrate: error: {}:{}: {}\n", where, line, message);
  } else {
    fmt::print(stderr, "mhd calibrate: error: {}: {}\n", where, message);
  }
}

void print_calibration_diagnostics(const mhd::Diagnostics& diagnostics) {
  for (const mhd::Diagnostic& d : diagnostics) print_error(d.where.file, d.where.line, d.message);
}

struct LoadedRig {
  mhd::SceneDescription scene;
  mhd::Rig rig;
};

std::optional<LoadedRig> load_rig(const std::string& file) {
  mhd::Result<mhd::SceneDescription> read = mhd::read_scene_file(file);
  if (!read.ok()) {
    print_calibration_diagnostics(read.diagnostics());
    return std::nullopt;
  }
  const mhd::Result<mhd::Rig, std::vector<mhd::RigError>> built = mhd::Rig::from_scene(*read);
  if (!built.ok()) {
    for (const mhd::RigError& e : built.error()) print_error(e.where.file.empty() ? file : e.where.file, e.where.line, e.message);
    return std::nullopt;
  }
  return LoadedRig{std::move(*read), *built};
}

bool write_text(const std::string& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) {
    print_error(file, 0, "cannot write");
    return false;
  }
  return true;
}

int synthesize(const CalibrateOptions& o, const mhd::Rig& rig) {
  mhd::SynthesisOptions s;
  s.samples = o.count;
  s.seed = o.seed;
  s.half_range_m = o.half_range_m;
  s.sensor_noise_m = o.noise_mm * 1e-3;
  s.hip_noise_m = o.noise_mm * 1e-3;
  s.sensor_noise_rad = o.angle_noise_deg * kRadPerDeg;
  s.truth.p_S_robot_m = Eigen::Vector3d(o.sr_mm[0], o.sr_mm[1], o.sr_mm[2]) * 1e-3;
  s.truth.p_R_phantom_m = Eigen::Vector3d(o.rp_mm[0], o.rp_mm[1], o.rp_mm[2]) * 1e-3;
  s.truth.psi_rad = o.psi_deg * kRadPerDeg;
  const std::vector<std::string> comments = mhd::describe_synthesis(s);
  if (!write_text(o.samples, mhd::format_calibration_samples(mhd::synthesize_samples(rig, s), comments))) return 1;
  fmt::print("wrote {} samples to {}\n", o.count, o.samples);
  for (const std::string& c : comments) fmt::print("  {}\n", c);
  return 0;
}

std::string default_output(const std::string& rig) {
  const fs::path p(rig);
  return (p.parent_path() / (p.stem().string() + ".calibrated.xml")).string();
}

int calibrate(const CalibrateOptions& o, const LoadedRig& loaded) {
  const mhd::Result<std::vector<mhd::CalibrationSample>> read = mhd::read_calibration_samples(o.samples);
  if (!read.ok()) {
    print_calibration_diagnostics(read.error());
    return 1;
  }
  if (const mhd::Diagnostics lifts = mhd::lift_problems(loaded.rig, read.value(), o.samples); !lifts.empty()) {
    print_calibration_diagnostics(lifts);
    return 1;
  }
  mhd::CalibrationOptions options;
  options.split = *mhd::offset_split_from_string(o.split);
  options.estimate_psi = !o.no_psi;
  const mhd::Result<mhd::CalibrationFit, mhd::CalibrationError> outcome = mhd::calibrate_rig(loaded.rig, read.value(), options);
  if (!outcome.ok()) {
    print_error(o.samples, 0, outcome.error().message + "; no rig written");
    return 1;
  }
  const mhd::CalibrationFit& result = *outcome;
  fmt::print("{} samples from {}, rig {}\n", read.value().size(), o.samples, o.rig);
  fmt::print("{}", mhd::format_calibration_report(result, options.split));
  if (!o.residuals.empty()) {
    if (!write_text(o.residuals, mhd::format_residuals_csv(loaded.rig, read.value(), result))) return 1;
    fmt::print("wrote residuals to {}\n", o.residuals);
  }
  const std::string output = o.output.empty() ? default_output(o.rig) : o.output;
  const mhd::Result<mhd::WrittenRig, std::string> written = mhd::write_calibrated_rig(
      loaded.scene, loaded.rig, result.after, output, mhd::calibration_note_lines(result, o.samples, options.split));
  if (!written.ok()) {
    print_error("", 0, written.error());
    return 1;
  }
  fmt::print("wrote {} (calibrated copy of {})\n", output, written->frames_file.string());
  return 0;
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto o = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Fit the rig's sensor->robot->PHANToM offsets and yaw psi to samples; write the calibrated rig");
  cmd->add_option("samples", o->samples, "Samples CSV (read; written with --synthesize)")
      ->required()
      ->type_name("SAMPLES.csv");
  cmd->add_option("--rig", o->rig, "Scene or rig XML holding the rig frames")->required()->type_name("RIG.xml");
  cmd->add_option("-o,--output", o->output, "Calibrated rig XML (default: RIG.calibrated.xml next to RIG)")
      ->type_name("OUT.xml");
  cmd->add_option("--residuals", o->residuals, "Also write per-sample residuals before/after (CSV)")
      ->type_name("FILE.csv");
  cmd->add_option("--split", o->split, "How SR and RP share the fitted offset: even, hold-sr, hold-rp")
      ->check(CLI::IsMember({"even", "hold-sr", "hold-rp"}))
      ->capture_default_str();
  cmd->add_flag("--no-psi", o->no_psi, "Keep psi at 0 (the thesis's six-offset fit)");
  cmd->add_flag("--synthesize", o->synthesize, "Write synthetic samples to SAMPLES.csv instead of calibrating");
  cmd->add_option("--samples", o->count, "With --synthesize: how many")->check(CLI::Range(1, 10000000))->capture_default_str();
  cmd->add_option("--seed", o->seed, "With --synthesize: random seed")->capture_default_str();
  cmd->add_option("--range-m", o->half_range_m, "With --synthesize: base x, z within +-this")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--noise-mm", o->noise_mm, "With --synthesize: tracker noise sigma per axis (station and HIP)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--angle-noise-deg", o->angle_noise_deg, "With --synthesize: station orientation noise sigma")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--psi-deg", o->psi_deg, "With --synthesize: true psi")->capture_default_str();
  cmd->add_option("--sr-mm", o->sr_mm, "With --synthesize: true SR x,y,z in base_sensor (thesis calibrated)")
      ->expected(3)
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--rp-mm", o->rp_mm, "With --synthesize: true RP x,y,z in robot (thesis calibrated)")
      ->expected(3)
      ->delimiter(',')
      ->capture_default_str();
  cmd->footer(
      "SAMPLES.csv columns (any order, more allowed): sensor_x_m,sensor_y_m,sensor_z_m,sensor_qw,sensor_qx,\n"
      "sensor_qy,sensor_qz (base station in is900), theta1_rad,theta2_rad,theta3_rad, hip_x_m,hip_y_m,hip_z_m\n"
      "(measured HIP in the world). Errors go to stderr as mhd calibrate: error: FILE:LINE: MESSAGE.");
  cmd->callback([o] {
    const std::optional<LoadedRig> loaded = load_rig(o->rig);
    if (!loaded) mhd::cli::exit_with(1);
    mhd::cli::exit_with(o->synthesize ? synthesize(*o, loaded->rig) : calibrate(*o, *loaded));
  });
}
