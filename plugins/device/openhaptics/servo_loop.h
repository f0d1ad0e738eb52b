#pragma once
// The meeting of OpenHaptics' servo loop (its scheduler thread, about 1 kHz) and MHD's
// haptic tick, with no lock on either side: the servo callback publishes the tool's state
// through one seqlock and takes the latest force from another. Each servo frame renders
// zero force unless force output is armed, the force is fresher than command_timeout_s,
// the reading is finite and no fault is latched; a fault, once seen, stays until close.

#include "hd_runtime.h"
#include "realtime/seqlock.h"

#include <array>
#include <atomic>
#include <cstdint>

namespace mhd_openhaptics {

/// What the servo loop saw, in HDAPI units (mm, mm/s).
struct ToolState {
  std::array<double, 3> p_D_mm{};
  std::array<double, 3> v_D_mm_s{};
  std::array<double, 4> q_D_wxyz{1.0, 0.0, 0.0, 0.0};
  std::uint32_t buttons = 0;
  std::uint64_t frame = 0;   ///< servo frames completed; 0 before the first
  double servo_time_s = 0.0; ///< steady clock at that frame
};

/// The arm's joints as the servo loop last read them: HD_CURRENT_JOINT_ANGLES, then
/// HD_CURRENT_GIMBAL_ANGLES (zero on a device without gimbal encoders).
struct ArmJoints {
  std::array<double, 6> angles_rad{};
  std::uint64_t frame = 0;  ///< the servo frame they are from; 0 before the first
};

enum class Fault : int { None = 0, DeviceError, NonFiniteReading, WarmMotors };

class ServoLoop {
 public:
  ServoLoop(const HdCalls& hd, HHD device, double command_timeout_s, double motor_temperature_limit) noexcept
      : hd_(hd), device_(device), command_timeout_s_(command_timeout_s),
        motor_temperature_limit_(motor_temperature_limit) {}

  /// The HDAPI callback; user_data is the ServoLoop.
  static HDCallbackCode frame_callback(void* user_data) noexcept;

  // ---- the haptic thread's side: lock-free, allocation-free -------------------------
  [[nodiscard]] ToolState state() const noexcept;
  [[nodiscard]] ArmJoints joints() const noexcept;
  void command(const std::array<double, 3>& force_D_N) noexcept;
  [[nodiscard]] Fault fault() const noexcept { return static_cast<Fault>(fault_.load(std::memory_order_acquire)); }
  [[nodiscard]] HDErrorInfo fault_error() const noexcept;
  [[nodiscard]] double fault_value() const noexcept { return fault_value_.load(std::memory_order_acquire); }

  // ---- start and stop ------------------------------------------------------------------
  void arm(bool armed) noexcept { armed_.store(armed, std::memory_order_release); }
  /// Frames that rendered zero because the newest force was older than command_timeout_s.
  [[nodiscard]] std::uint64_t stale_command_frames() const noexcept {
    return stale_frames_.load(std::memory_order_relaxed);
  }
  /// The last frame that rendered zero force, 0 before any.
  [[nodiscard]] std::uint64_t last_zero_frame() const noexcept {
    return last_zero_frame_.load(std::memory_order_acquire);
  }

  static double steady_now_s() noexcept;

 private:
  struct Reading {
    ToolState tool;
    bool finite = true;  ///< position, velocity and transform
    std::array<double, hd::kMaxMotors> motor_temperature{};
    std::array<double, 6> joint_angles_rad{};
  };
  HDCallbackCode frame() noexcept;
  Reading read_tool() const noexcept;
  std::array<double, 3> force_to_render(const Reading& reading, double now_s) noexcept;
  void latch(Fault fault, double value) noexcept;
  void latch_device_error() noexcept;
  void publish(const Reading& reading, double now_s) noexcept;

  const HdCalls& hd_;
  HHD device_;
  double command_timeout_s_;
  double motor_temperature_limit_;

  mhd::realtime::Seqlock<13> state_;   ///< p, v, q, buttons, frame, time
  mhd::realtime::Seqlock<4> command_;  ///< force, when written (steady clock)
  mhd::realtime::Seqlock<7> joints_;   ///< joint and gimbal angles, frame
  std::atomic<bool> armed_{false};
  std::atomic<int> fault_{static_cast<int>(Fault::None)};
  std::atomic<unsigned> fault_code_{0};
  std::atomic<int> fault_internal_{0};
  std::atomic<double> fault_value_{0.0};
  std::atomic<std::uint64_t> stale_frames_{0};
  std::atomic<std::uint64_t> last_zero_frame_{0};
  std::uint64_t frames_ = 0;  ///< servo thread only
};

}  // namespace mhd_openhaptics
