#include "servo_loop.h"

#include <chrono>
#include <cmath>

namespace mhd_openhaptics {
namespace {

bool all_finite(const double* values, int count) noexcept {
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) return false;
  }
  return true;
}

/// The rotation of HDAPI's column-major 4x4 transform as a unit quaternion w, x, y, z.
std::array<double, 4> quaternion_of(const std::array<double, 16>& m) noexcept {
  const auto r = [&](int row, int col) { return m[static_cast<std::size_t>(col * 4 + row)]; };
  const double trace = r(0, 0) + r(1, 1) + r(2, 2);
  std::array<double, 4> q{};
  if (trace > 0.0) {
    const double s = 2.0 * std::sqrt(trace + 1.0);
    q = {0.25 * s, (r(2, 1) - r(1, 2)) / s, (r(0, 2) - r(2, 0)) / s, (r(1, 0) - r(0, 1)) / s};
  } else if (r(0, 0) > r(1, 1) && r(0, 0) > r(2, 2)) {
    const double s = 2.0 * std::sqrt(1.0 + r(0, 0) - r(1, 1) - r(2, 2));
    q = {(r(2, 1) - r(1, 2)) / s, 0.25 * s, (r(0, 1) + r(1, 0)) / s, (r(0, 2) + r(2, 0)) / s};
  } else if (r(1, 1) > r(2, 2)) {
    const double s = 2.0 * std::sqrt(1.0 + r(1, 1) - r(0, 0) - r(2, 2));
    q = {(r(0, 2) - r(2, 0)) / s, (r(0, 1) + r(1, 0)) / s, 0.25 * s, (r(1, 2) + r(2, 1)) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + r(2, 2) - r(0, 0) - r(1, 1));
    q = {(r(1, 0) - r(0, 1)) / s, (r(0, 2) + r(2, 0)) / s, (r(1, 2) + r(2, 1)) / s, 0.25 * s};
  }
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(norm > 0.0) || !std::isfinite(norm)) return {1.0, 0.0, 0.0, 0.0};
  for (double& c : q) c /= norm;
  return q;
}

}  // namespace

double ServoLoop::steady_now_s() noexcept {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

HDCallbackCode ServoLoop::frame_callback(void* user_data) noexcept {
  return static_cast<ServoLoop*>(user_data)->frame();
}

/// One servo frame: read the tool, choose the force, render it, note the driver's
/// errors, publish the state.
HDCallbackCode ServoLoop::frame() noexcept {
  hd_.hdBeginFrame(device_);
  const Reading reading = read_tool();
  const double now_s = steady_now_s();
  const std::array<double, 3> force = force_to_render(reading, now_s);
  hd_.hdSetDoublev(hd::kCurrentForce, force.data());
  hd_.hdEndFrame(device_);
  latch_device_error();
  publish(reading, now_s);
  return hd::kCallbackContinue;
}

ServoLoop::Reading ServoLoop::read_tool() const noexcept {
  Reading r;
  std::array<double, 16> transform{};
  transform[0] = transform[5] = transform[10] = transform[15] = 1.0;
  int buttons = 0;
  hd_.hdGetDoublev(hd::kCurrentPosition, r.tool.p_D_mm.data());
  hd_.hdGetDoublev(hd::kCurrentVelocity, r.tool.v_D_mm_s.data());
  hd_.hdGetDoublev(hd::kCurrentTransform, transform.data());
  hd_.hdGetIntegerv(hd::kCurrentButtons, &buttons);
  hd_.hdGetDoublev(hd::kMotorTemperature, r.motor_temperature.data());
  hd_.hdGetDoublev(hd::kCurrentJointAngles, r.joint_angles_rad.data());
  hd_.hdGetDoublev(hd::kCurrentGimbalAngles, r.joint_angles_rad.data() + 3);
  r.tool.q_D_wxyz = quaternion_of(transform);
  r.tool.buttons = static_cast<std::uint32_t>(buttons);
  r.finite = all_finite(r.tool.p_D_mm.data(), 3) && all_finite(r.tool.v_D_mm_s.data(), 3) &&
             all_finite(transform.data(), 16);
  return r;
}

std::array<double, 3> ServoLoop::force_to_render(const Reading& reading, double now_s) noexcept {
  if (!reading.finite) latch(Fault::NonFiniteReading, 0.0);
  for (const double t : reading.motor_temperature) {
    if (t >= motor_temperature_limit_) latch(Fault::WarmMotors, t);
  }
  const std::array<double, 4> c = command_.read();
  const bool fresh = now_s - c[3] <= command_timeout_s_;
  const bool armed = armed_.load(std::memory_order_acquire);
  if (armed && !fresh) stale_frames_.fetch_add(1, std::memory_order_relaxed);
  if (!armed || !fresh || fault() != Fault::None) {
    last_zero_frame_.store(frames_ + 1, std::memory_order_release);
    return {0.0, 0.0, 0.0};
  }
  return {c[0], c[1], c[2]};
}

void ServoLoop::latch(Fault fault, double value) noexcept {
  int none = static_cast<int>(Fault::None);
  if (fault_.load(std::memory_order_relaxed) != none) return;
  fault_value_.store(value, std::memory_order_relaxed);
  fault_.compare_exchange_strong(none, static_cast<int>(fault), std::memory_order_acq_rel);
}

void ServoLoop::latch_device_error() noexcept {
  const HDErrorInfo error = hd_.hdGetError();
  if (error.errorCode == hd::kSuccess) return;
  if (fault() == Fault::None) {
    fault_code_.store(error.errorCode, std::memory_order_relaxed);
    fault_internal_.store(error.internalErrorCode, std::memory_order_relaxed);
  }
  latch(Fault::DeviceError, 0.0);
}

HDErrorInfo ServoLoop::fault_error() const noexcept {
  return HDErrorInfo{fault_code_.load(std::memory_order_acquire), fault_internal_.load(std::memory_order_acquire),
                     device_};
}

void ServoLoop::publish(const Reading& reading, double now_s) noexcept {
  ++frames_;
  const ToolState& t = reading.tool;
  state_.write({t.p_D_mm[0], t.p_D_mm[1], t.p_D_mm[2], t.v_D_mm_s[0], t.v_D_mm_s[1], t.v_D_mm_s[2], t.q_D_wxyz[0],
                t.q_D_wxyz[1], t.q_D_wxyz[2], t.q_D_wxyz[3], static_cast<double>(t.buttons),
                static_cast<double>(frames_), now_s});
  const std::array<double, 6>& j = reading.joint_angles_rad;
  joints_.write({j[0], j[1], j[2], j[3], j[4], j[5], static_cast<double>(frames_)});
}

ArmJoints ServoLoop::joints() const noexcept {
  const std::array<double, 7> s = joints_.read();
  ArmJoints out;
  for (std::size_t i = 0; i < out.angles_rad.size(); ++i) out.angles_rad[i] = s[i];
  out.frame = static_cast<std::uint64_t>(s[6]);
  return out;
}

ToolState ServoLoop::state() const noexcept {
  const std::array<double, 13> s = state_.read();
  ToolState t;
  t.p_D_mm = {s[0], s[1], s[2]};
  t.v_D_mm_s = {s[3], s[4], s[5]};
  t.q_D_wxyz = {s[6], s[7], s[8], s[9]};
  t.buttons = static_cast<std::uint32_t>(s[10]);
  t.frame = static_cast<std::uint64_t>(s[11]);
  t.servo_time_s = s[12];
  return t;
}

void ServoLoop::command(const std::array<double, 3>& force_D_N) noexcept {
  command_.write({force_D_N[0], force_D_N[1], force_D_N[2], steady_now_s()});
}

}  // namespace mhd_openhaptics
