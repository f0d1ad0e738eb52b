#include "fake_hardware.h"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>

namespace mhd::fake {
namespace {

std::string env(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v != nullptr ? v : fallback;
}

}  // namespace

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Config Config::from_environment() {
  static const std::map<std::string, Fault> faults{
      {"none", Fault::None},
      {"unplugged", Fault::Unplugged},
      {"error_every_call", Fault::ErrorEveryCall},
      {"comm_error", Fault::CommError},
      {"nan_position", Fault::NanPosition},
      {"servo_stall", Fault::ServoStall},
      {"warm_motors", Fault::WarmMotors},
      {"needs_manual_calibration", Fault::NeedsManualCalibration},
      {"needs_update", Fault::NeedsUpdate},
      {"frozen_timestamp", Fault::FrozenTimestamp},
      {"old_library", Fault::OldLibrary},
      {"hang", Fault::Hang},
      {"dropout", Fault::Dropout}};
  Config c;
  const auto it = faults.find(env("MHD_FAKE_FAULT", "none"));
  if (it == faults.end()) {
    std::fprintf(stderr, "fake vendor library: unknown MHD_FAKE_FAULT\n");
    std::abort();
  }
  c.fault = it->second;
  c.fault_after_s = std::atof(env("MHD_FAKE_FAULT_AFTER_S", "1").c_str());
  c.max_force_N = std::atof(env("MHD_FAKE_MAX_FORCE_N", "3.3").c_str());
  std::istringstream in(env("MHD_FAKE_WORKSPACE_MM", "-80 -60 -35 80 60 35"));
  for (double& w : c.workspace_mm) in >> w;
  c.model = env("MHD_FAKE_MODEL", "omega3");
  return c;
}

HardwareLog::HardwareLog() {
  const std::string path = env("MHD_FAKE_LOG", "");
  if (path.empty()) return;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND, 0644);
  const char* header = "t_s,event,a,b,c\n";
  if (fd_ >= 0) (void)!::write(fd_, header, std::strlen(header));
}

HardwareLog::~HardwareLog() {
  if (fd_ >= 0) ::close(fd_);
}

void HardwareLog::add_at(double t_s, const char* event, double a, double b, double c) const {
  if (fd_ < 0) return;
  std::array<char, 160> line{};
  const int n = std::snprintf(line.data(), line.size(), "%.6f,%s,%.9g,%.9g,%.9g\n", t_s, event, a, b, c);
  if (n > 0) (void)!::write(fd_, line.data(), static_cast<std::size_t>(n));
}

void Hand::step(double dt_s, const std::array<double, 3>& motor_force_N) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr double kMass_kg = 0.1;
  constexpr double kSpring_N_per_m = 300.0;
  constexpr double kDamping_Ns_per_m = 7.0;
  t_s_ += dt_s;
  std::array<double, 3> target_m{};
  target_m[static_cast<std::size_t>(up_)] = 0.02 - 0.05 * 0.5 * (1.0 - std::cos(2.0 * kPi * 0.5 * t_s_));
  for (std::size_t i = 0; i < 3; ++i) {
    const double f_N = kSpring_N_per_m * (target_m[i] - p_m_[i]) - kDamping_Ns_per_m * v_m_s_[i] + motor_force_N[i];
    v_m_s_[i] += f_N / kMass_kg * dt_s;
    p_m_[i] += v_m_s_[i] * dt_s;
  }
}

double norm(const std::array<double, 3>& f) { return std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]); }

}  // namespace mhd::fake
