// openhaptics: a 3D Systems device (Touch, Touch X, the PHANToM Premium family) through
// OpenHaptics' HDAPI, loaded from libHD.so when the plugin opens. HDAPI runs its own servo
// loop; ServoLoop meets MHD's haptic tick there without a lock (servo_loop.h). Device
// frame D is HDAPI's (x right, y up, z towards the user), in metres. With
// joint_state_topic, the arm's joint angles go to ROS 2 displays (arm_joint_publisher.h).
#include "arm_joint_publisher.h"
#include "hd_runtime.h"
#include "servo_loop.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>

namespace mhd_openhaptics {
namespace {

constexpr double kMmPerM = 1000.0;
/// device_read fails once the servo loop has not completed a frame for this long.
constexpr double kServoStaleS = 0.1;
/// start() and stop() wait this long for the servo loop to run a frame.
constexpr double kServoWaitS = 1.0;

std::string number(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%g", value);
  return text.data();
}

/// Waits (sleeping 1 ms) until done() or kServoWaitS passes.
template <class Done>
bool wait_for_servo(Done&& done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(kServoWaitS);
  while (!done()) {
    if (std::chrono::steady_clock::now() >= give_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

}  // namespace

class OpenHaptics {
 public:
  static constexpr std::array kParams = mhd::sdk::join(std::array{
      mhd::sdk::text("library", "libHD.so", "the OpenHaptics runtime to load (a name the loader finds, or a path)"),
      mhd::sdk::text("device", "default", "the device's name as configured in Touch_Setup; 'default' for the default"),
      mhd::sdk::number("command_timeout_s", "s", "0.01",
                       "the servo loop renders zero force when MHD's last force is older than this",
                       mhd::sdk::between(0.002, 0.1)),
      mhd::sdk::number("motor_temperature_limit", "", "0.9",
                       "a motor temperature (HDAPI's 0..1 scale) at which the run ends with a fault",
                       mhd::sdk::between(0.1, 1.0)),
      mhd::sdk::choice("calibration", "auto|refuse", "auto",
                       "auto: update a calibration the device can update itself; refuse: end the open instead"),
      mhd::sdk::text("joint_state_topic", nullptr,
                     "the ROS topic of the arm's sensor_msgs/JointState (none: not published); the DDS parameters "
                     "below apply to it"),
      mhd::sdk::number("joint_state_rate_hz", "Hz", "100", "how often the joint states are published",
                       mhd::sdk::between(1, 1000)),
  }, mhd::dds::kEndpointParams);

  OpenHaptics(const mhd_host& host, const mhd::sdk::Params& params)
      : host_(host), runtime_(load_hd(params.text("library"))), hd_(runtime_->calls()),
        calibration_auto_(params.text("calibration") == "auto") {
    const std::string name = params.text("device");
    device_ = hd_.hdInitDevice(name == "default" ? nullptr : name.c_str());
    const HDErrorInfo error = hd_.hdGetError();
    if (error.errorCode != hd::kSuccess || device_ == hd::kInvalidHandle) {
      device_ = hd::kInvalidHandle;
      throw std::runtime_error("hdInitDevice('" + name + "'): " + describe(hd_, error));
    }
    try {
      hd_.hdMakeCurrentDevice(device_);
      read_device_info();
    } catch (...) {
      hd_.hdDisableDevice(device_);
      throw;
    }
    servo_ = std::make_unique<ServoLoop>(hd_, device_, params.number("command_timeout_s"),
                                         params.number("motor_temperature_limit"));
    if (const auto topic = params.optional_text("joint_state_topic")) {
      joints_ = std::make_unique<ArmJointPublisher>(
          *servo_, mhd::dds::read_endpoint(params, host.scene_file),
          mhd::dds::checked_ros_name("joint_state_topic", *topic), params.number("joint_state_rate_hz"));
    }
  }
  OpenHaptics(const OpenHaptics&) = delete;
  OpenHaptics& operator=(const OpenHaptics&) = delete;
  ~OpenHaptics() {
    end_servo_loop();
    hd_.hdDisableDevice(device_);
  }

  /// The scheduler, the calibration check, the servo loop's first frame, then force output.
  void start() {
    hd_.hdStartScheduler();
    scheduler_running_ = true;
    check("hdStartScheduler");
    check_calibration();
    servo_handle_ = hd_.hdScheduleAsynchronous(&ServoLoop::frame_callback, servo_.get(), hd::kMaxSchedulerPriority);
    check("hdScheduleAsynchronous");
    servo_scheduled_ = true;
    if (!wait_for_servo([&] { return servo_->state().frame > 0; })) {
      throw std::runtime_error("the OpenHaptics servo loop ran no frame within " + number(kServoWaitS) + " s");
    }
    throw_if_faulted();
    hd_.hdEnable(hd::kForceOutput);
    check("hdEnable(HD_FORCE_OUTPUT)");
    servo_->arm(true);
    if (joints_) joints_->start();
  }

  /// Zero force in a servo frame, force output off, the servo loop and scheduler ended.
  void stop() {
    const bool zero_rendered = end_servo_loop();
    if (!zero_rendered) throw std::runtime_error("the servo loop rendered no zero-force frame before it stopped");
  }

  void device_info(mhd_device_info& out) const { out = info_; }

  void device_read(mhd_device_state& out) {
    throw_if_faulted();
    const ToolState tool = servo_->state();
    check_servo_progress(tool.frame);
    out = mhd_device_state{};
    out.timestamp_s = mhd::sdk::host_now(host_);
    for (std::size_t i = 0; i < 3; ++i) {
      out.p_D_tool_m[i] = tool.p_D_mm[i] / kMmPerM;
      out.v_D_tool_mps[i] = tool.v_D_mm_s[i] / kMmPerM;
    }
    for (std::size_t i = 0; i < 4; ++i) out.q_D_tool_wxyz[i] = tool.q_D_wxyz[i];
    out.buttons = tool.buttons;
  }

  // The host has clamped the force to max_force_N. A fault never refuses a write: the
  // servo loop renders zero anyway, and the host's zero must be confirmed.
  void device_write(const mhd_device_command& command) {
    servo_->command({command.force_D_N[0], command.force_D_N[1], command.force_D_N[2]});
  }

  std::size_t counters(std::span<mhd_counter> out) const {
    const std::array<mhd_counter, 3> all{
        mhd_counter{"servo_frames", servo_->state().frame},
        mhd_counter{"stale_command_frames", servo_->stale_command_frames()},
        mhd_counter{"joint_states_published", joints_ ? joints_->published() : 0},
    };
    for (std::size_t i = 0; i < out.size() && i < all.size(); ++i) out[i] = all[i];
    return all.size();
  }

 private:
  void check(const char* call) const {
    const HDErrorInfo error = hd_.hdGetError();
    if (error.errorCode != hd::kSuccess) throw std::runtime_error(std::string(call) + ": " + describe(hd_, error));
  }

  double get_double(HDenum parameter, const char* name) const {
    double value = 0.0;
    hd_.hdGetDoublev(parameter, &value);
    check(name);
    return value;
  }

  void read_device_info() {
    const char* model = hd_.hdGetString(hd::kDeviceModelType);
    check("hdGetString(HD_DEVICE_MODEL_TYPE)");
    model_ = model != nullptr ? model : "unknown model";
    int dof_in = 0;
    int dof_out = 0;
    hd_.hdGetIntegerv(hd::kInputDof, &dof_in);
    hd_.hdGetIntegerv(hd::kOutputDof, &dof_out);
    check("hdGetIntegerv(HD_INPUT_DOF, HD_OUTPUT_DOF)");
    std::array<double, 6> workspace_mm{};
    hd_.hdGetDoublev(hd::kUsableWorkspaceDimensions, workspace_mm.data());
    check("hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS)");
    info_ = mhd_device_info{};
    info_.max_force_N = get_double(hd::kNominalMaxForce, "hdGetDoublev(HD_NOMINAL_MAX_FORCE)");
    info_.max_stiffness_N_per_m =
        get_double(hd::kNominalMaxStiffness, "hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS)") * kMmPerM;
    // Torque output (the 6-DOF PHANToM Premium) is not rendered: MHD's proxy is a point.
    info_.dof_in = dof_in >= 6 ? 6u : 3u;
    info_.dof_out = 3;
    info_.workspace_box_count = 1;
    for (std::size_t i = 0; i < 3; ++i) {
      info_.workspace[0].min_m[i] = workspace_mm[i] / kMmPerM;
      info_.workspace[0].max_m[i] = workspace_mm[i + 3] / kMmPerM;
    }
    if (dof_out < 3) {
      throw std::runtime_error("the device '" + model_ + "' reports " + std::to_string(dof_out) +
                               " output DOF: MHD needs a force-feedback device (3 or more)");
    }
  }

  struct Calibration {
    const HdCalls* hd;
    HHD device;
    bool update;
    int status = 0;
  };
  static HDCallbackCode calibrate(void* user_data) noexcept {
    auto& c = *static_cast<Calibration*>(user_data);
    c.hd->hdBeginFrame(c.device);
    c.status = c.hd->hdCheckCalibration();
    if (c.status == hd::kCalibrationNeedsUpdate && c.update) {
      int style = 0;
      c.hd->hdGetIntegerv(hd::kCalibrationStyle, &style);
      c.hd->hdUpdateCalibration(static_cast<HDenum>(style));
    }
    c.hd->hdEndFrame(c.device);
    return hd::kCallbackDone;
  }

  void check_calibration() {
    Calibration c{&hd_, device_, calibration_auto_};
    hd_.hdScheduleSynchronous(&OpenHaptics::calibrate, &c, hd::kMaxSchedulerPriority);
    check("hdCheckCalibration");
    if (c.status == hd::kCalibrationNeedsManualInput) {
      throw std::runtime_error("the device '" + model_ +
                               "' needs calibrating by hand: put the stylus in its inkwell (Touch) or at its "
                               "reset position, or run the vendor's diagnostic tool, then start again");
    }
    if (c.status == hd::kCalibrationNeedsUpdate && !calibration_auto_) {
      throw std::runtime_error("the device '" + model_ +
                               "' needs a calibration update, and calibration is 'refuse' in the scene");
    }
  }

  /// Fails once the servo loop has completed no frame for kServoStaleS of this thread's
  /// own running time: a gap between two reads (this process stopped as a whole, say)
  /// restarts the count, since the servo thread was stopped too.
  void check_servo_progress(std::uint64_t frame) {
    const double now_s = ServoLoop::steady_now_s();
    if (frame != last_frame_ || now_s - last_read_s_ > kServoStaleS / 2) {
      last_frame_ = frame;
      unchanged_since_s_ = now_s;
    }
    last_read_s_ = now_s;
    if (now_s - unchanged_since_s_ > kServoStaleS) {
      throw std::runtime_error("the OpenHaptics servo loop has run no frame for " +
                               number((now_s - unchanged_since_s_) * 1000.0) + " ms: the driver stalled");
    }
  }

  void throw_if_faulted() const {
    switch (servo_->fault()) {
      case Fault::None:
        return;
      case Fault::DeviceError:
        throw std::runtime_error("device fault in the servo loop: " + describe(hd_, servo_->fault_error()));
      case Fault::NonFiniteReading:
        throw std::runtime_error("the driver returned a non-finite tool position, velocity or transform; force "
                                 "was zeroed in that servo frame");
      case Fault::WarmMotors:
        throw std::runtime_error("a motor reached temperature " + number(servo_->fault_value()) +
                                 " (motor_temperature_limit): let the device cool down");
    }
  }

  /// Disarms the servo loop, waits for a zero-force frame, then turns force output off
  /// and ends the loop and the scheduler. Says whether a zero frame was rendered.
  bool end_servo_loop() noexcept {
    if (joints_) joints_->stop();
    if (!scheduler_running_) return true;
    bool zero_rendered = true;
    if (servo_scheduled_) {
      servo_->arm(false);
      const std::uint64_t after = servo_->state().frame;
      zero_rendered = wait_for_servo([&] { return servo_->last_zero_frame() > after; });
    }
    hd_.hdDisable(hd::kForceOutput);
    if (servo_scheduled_) hd_.hdUnschedule(servo_handle_);
    servo_scheduled_ = false;
    hd_.hdStopScheduler();
    scheduler_running_ = false;
    return zero_rendered;
  }

  mhd_host host_;
  std::unique_ptr<HdRuntime> runtime_;
  const HdCalls& hd_;
  bool calibration_auto_;
  HHD device_ = hd::kInvalidHandle;
  std::string model_;
  mhd_device_info info_{};
  std::unique_ptr<ServoLoop> servo_;
  std::unique_ptr<ArmJointPublisher> joints_;  ///< null: no joint_state_topic
  HDSchedulerHandle servo_handle_ = 0;
  bool scheduler_running_ = false;
  bool servo_scheduled_ = false;
  std::uint64_t last_frame_ = 0;   ///< device_read's view of the servo loop's progress
  double unchanged_since_s_ = 0.0;
  double last_read_s_ = 0.0;
};

}  // namespace mhd_openhaptics

MHD_PLUGIN_ENTRY(mhd_openhaptics::OpenHaptics,
                 {.kind = MHD_KIND_DEVICE, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "3D Systems Touch, Touch X and PHANToM Premium through OpenHaptics HDAPI (libHD)"})
