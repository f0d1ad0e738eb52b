#include "simulated_headset.h"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

namespace mhd::fake_openxr {
namespace {

std::string env(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v != nullptr ? v : fallback;
}

Fault fault_from(const std::string& name) {
  if (name == "none") return Fault::None;
  if (name == "tracking_lost") return Fault::TrackingLost;
  if (name == "nan_pose") return Fault::NanPose;
  if (name == "session_lost") return Fault::SessionLost;
  if (name == "no_system") return Fault::NoSystem;
  if (name == "hang") return Fault::Hang;
  std::fprintf(stderr, "fake OpenXR runtime: unknown MHD_FAKE_FAULT '%s'\n", name.c_str());
  std::abort();
}

}  // namespace

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

SimulatedHeadset::SimulatedHeadset()
    : fault_(fault_from(env("MHD_FAKE_FAULT", "none"))),
      fault_after_s_(std::atof(env("MHD_FAKE_FAULT_AFTER_S", "1").c_str())) {
  std::istringstream head(env("MHD_FAKE_HEAD_M", "-0.9 0 0.974"));
  for (double& p : p_head_m_) head >> p;
  const std::string path = env("MHD_FAKE_LOG", "");
  if (path.empty()) return;
  log_fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND, 0644);
  const char* header = "t_s,event,a,b,c\n";
  if (log_fd_ >= 0) (void)!::write(log_fd_, header, std::strlen(header));
}

SimulatedHeadset::~SimulatedHeadset() {
  if (log_fd_ >= 0) ::close(log_fd_);
}

bool SimulatedHeadset::struck() const noexcept {
  return fault_ != Fault::None && began_at_s_ >= 0.0 && now_s() - began_at_s_ >= fault_after_s_;
}

XrSpaceLocation SimulatedHeadset::locate() const noexcept {
  constexpr double kPi = 3.14159265358979323846;
  XrSpaceLocation location{};
  location.type = XR_TYPE_SPACE_LOCATION;
  location.locationFlags = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
                           XR_SPACE_LOCATION_POSITION_TRACKED_BIT | XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
  // A standing user sways 1 cm at 0.25 Hz; the head looks straight on.
  const double sway_m = 0.01 * std::sin(2.0 * kPi * 0.25 * now_s());
  location.pose.position = {static_cast<float>(p_head_m_[0]), static_cast<float>(p_head_m_[1] + sway_m),
                            static_cast<float>(p_head_m_[2])};
  location.pose.orientation = {0.0f, 0.0f, 0.0f, 1.0f};
  if (struck() && fault_ == Fault::TrackingLost) location.locationFlags = 0;
  if (struck() && fault_ == Fault::NanPose) location.pose.position.y = std::numeric_limits<float>::quiet_NaN();
  return location;
}

void SimulatedHeadset::log(const char* event, double a, double b, double c) const noexcept {
  if (log_fd_ < 0) return;
  std::array<char, 160> line{};
  const int n = std::snprintf(line.data(), line.size(), "%.6f,%s,%.9g,%.9g,%.9g\n", now_s(), event, a, b, c);
  if (n > 0) (void)!::write(log_fd_, line.data(), static_cast<std::size_t>(n));
}

}  // namespace mhd::fake_openxr
