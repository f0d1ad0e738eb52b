// The openhaptics plugin's ServoLoop, where HDAPI's servo thread and MHD's haptic thread
// meet without a lock, driven through a table of stand-in HDAPI calls: what each frame
// renders (armed, fresh, finite, no fault), the faults it latches, and both threads at
// full speed at once (ThreadSanitizer runs this: tools/ci/sanitizers.sh tsan).
#include "servo_loop.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace mhd_openhaptics {
namespace {

/// The stand-in device: what the servo frame reads, and what it set. Touched only by the
/// thread that runs frames.
struct Stub {
  std::array<double, 3> p_mm{1.0, 2.0, 3.0};
  std::array<double, 16> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double motor_temperature = 0.2;
  HDerror error = hd::kSuccess;
  std::array<double, 3> force_N{};
  int frames = 0;
};
Stub g_stub;

void get_doublev(HDenum parameter, double* values) {
  switch (parameter) {
    case hd::kCurrentPosition:
      for (std::size_t i = 0; i < 3; ++i) values[i] = g_stub.p_mm[i];
      return;
    case hd::kCurrentVelocity:
      for (std::size_t i = 0; i < 3; ++i) values[i] = 0.0;
      return;
    case hd::kCurrentTransform:
      for (std::size_t i = 0; i < 16; ++i) values[i] = g_stub.transform[i];
      return;
    case hd::kMotorTemperature:
      for (int i = 0; i < hd::kMaxMotors; ++i) values[i] = g_stub.motor_temperature;
      return;
    case hd::kCurrentJointAngles:  // every angle the frame count: a torn read would mix two
    case hd::kCurrentGimbalAngles:
      for (std::size_t i = 0; i < 3; ++i) values[i] = static_cast<double>(g_stub.frames);
      return;
    default:
      return;
  }
}

HdCalls stub_calls() {
  HdCalls c{};
  c.hdBeginFrame = [](HHD) {};
  c.hdEndFrame = [](HHD) { ++g_stub.frames; };
  c.hdGetDoublev = &get_doublev;
  c.hdGetIntegerv = [](HDenum, int* v) { *v = 0; };
  c.hdSetDoublev = [](HDenum, const double* f) { g_stub.force_N = {f[0], f[1], f[2]}; };
  c.hdGetError = [] { return HDErrorInfo{std::exchange(g_stub.error, hd::kSuccess), 42, 0}; };
  return c;
}

class ServoLoopTest : public ::testing::Test {
 protected:
  void SetUp() override { g_stub = Stub{}; }
  HDCallbackCode frame() { return ServoLoop::frame_callback(&loop); }
  HdCalls calls = stub_calls();
  ServoLoop loop{calls, 0, /*command_timeout_s=*/0.05, /*motor_temperature_limit=*/0.9};
};

TEST_F(ServoLoopTest, AnArmedFreshForceIsRenderedAndTheStatePublished) {
  loop.arm(true);
  loop.command({1.0, -2.0, 0.5});
  EXPECT_EQ(frame(), hd::kCallbackContinue);
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{1.0, -2.0, 0.5}));
  const ToolState s = loop.state();
  EXPECT_EQ(s.frame, 1u);
  EXPECT_EQ(s.p_D_mm, g_stub.p_mm);
  EXPECT_EQ(s.q_D_wxyz, (std::array<double, 4>{1.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(loop.fault(), Fault::None);
}

TEST_F(ServoLoopTest, UnarmedOrStaleOrNeverCommandedRendersZero) {
  frame();  // never commanded
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{}));
  loop.command({1.0, 1.0, 1.0});
  frame();  // not armed
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{}));
  loop.arm(true);
  frame();
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{1.0, 1.0, 1.0}));
  std::this_thread::sleep_for(std::chrono::milliseconds(80));  // past command_timeout_s
  frame();
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{}));
  EXPECT_GE(loop.stale_command_frames(), 1u);
  EXPECT_EQ(loop.last_zero_frame(), 4u);
  loop.command({2.0, 0.0, 0.0});  // fresh again: rendered again
  frame();
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{2.0, 0.0, 0.0}));
}

TEST_F(ServoLoopTest, ANonFiniteReadingLatchesAFaultAndZeroesThatFrameAndAfter) {
  loop.arm(true);
  loop.command({1.0, 0.0, 0.0});
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -HUGE_VAL}) {
    SetUp();
    ServoLoop fresh(calls, 0, 0.05, 0.9);
    fresh.arm(true);
    fresh.command({1.0, 0.0, 0.0});
    g_stub.p_mm[1] = bad;
    ServoLoop::frame_callback(&fresh);
    EXPECT_EQ(fresh.fault(), Fault::NonFiniteReading);
    EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{}));
    g_stub.p_mm[1] = 0.0;  // finite again: the fault stays
    fresh.command({1.0, 0.0, 0.0});
    ServoLoop::frame_callback(&fresh);
    EXPECT_EQ(fresh.fault(), Fault::NonFiniteReading);
    EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{}));
  }
}

TEST_F(ServoLoopTest, ADeviceErrorIsLatchedWithItsCodesAndTheFirstOneKept) {
  loop.arm(true);
  loop.command({1.0, 0.0, 0.0});
  g_stub.error = hd::kCommError;
  frame();
  EXPECT_EQ(loop.fault(), Fault::DeviceError);
  EXPECT_EQ(loop.fault_error().errorCode, hd::kCommError);
  EXPECT_EQ(loop.fault_error().internalErrorCode, 42);
  g_stub.error = hd::kWarmMotors;
  loop.command({1.0, 0.0, 0.0});
  frame();
  EXPECT_EQ(loop.fault_error().errorCode, hd::kCommError);
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{}));
}

TEST_F(ServoLoopTest, AMotorAtItsTemperatureLimitLatchesAndOneBelowDoesNot) {
  loop.arm(true);
  loop.command({1.0, 0.0, 0.0});
  g_stub.motor_temperature = 0.899;
  frame();
  EXPECT_EQ(loop.fault(), Fault::None);
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{1.0, 0.0, 0.0}));
  g_stub.motor_temperature = 0.9;
  frame();
  EXPECT_EQ(loop.fault(), Fault::WarmMotors);
  EXPECT_DOUBLE_EQ(loop.fault_value(), 0.9);
  EXPECT_EQ(g_stub.force_N, (std::array<double, 3>{}));
}

TEST_F(ServoLoopTest, TheTransformsRotationBecomesAUnitQuaternion) {
  // 90 degrees about y, column-major: x -> -z, z -> x.
  g_stub.transform = {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  frame();
  const ToolState s = loop.state();
  EXPECT_NEAR(s.q_D_wxyz[0], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s.q_D_wxyz[1], 0.0, 1e-12);
  EXPECT_NEAR(s.q_D_wxyz[2], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s.q_D_wxyz[3], 0.0, 1e-12);
}

TEST_F(ServoLoopTest, TheJointAnglesArePublishedWithTheirFrame) {
  EXPECT_EQ(loop.joints().frame, 0u);
  frame();
  frame();
  const ArmJoints j = loop.joints();
  EXPECT_EQ(j.frame, 2u);
  for (const double a : j.angles_rad) EXPECT_EQ(a, 1.0);  // read before the second frame ended
}

// Both sides at full speed: the servo thread renders only forces that were commanded
// whole (each command is (k, k, k): a torn one would mix two), and the haptic side sees
// frame numbers that never go back, and joint angles read whole (a display's thread).
TEST_F(ServoLoopTest, BothThreadsAtFullSpeedNeverTearAForceOrGoBack) {
  loop.arm(true);
  std::atomic<bool> stop{false};
  std::atomic<int> torn{0};
  std::thread servo([&] {
    while (!stop.load()) {
      frame();
      const auto& f = g_stub.force_N;
      if (f[0] != f[1] || f[1] != f[2]) torn.fetch_add(1);
    }
  });
  std::uint64_t last_frame = 0;
  int went_back = 0;
  int torn_joints = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
  for (double k = 1.0; std::chrono::steady_clock::now() < end; k += 1.0) {
    loop.command({k, k, k});
    const ToolState s = loop.state();
    if (s.frame < last_frame) ++went_back;
    last_frame = s.frame;
    const ArmJoints j = loop.joints();
    for (const double a : j.angles_rad) torn_joints += a != j.angles_rad[0] ? 1 : 0;
  }
  stop.store(true);
  servo.join();
  EXPECT_EQ(torn.load(), 0);
  EXPECT_EQ(went_back, 0);
  EXPECT_EQ(torn_joints, 0);
  EXPECT_GT(last_frame, 100u);
}

}  // namespace
}  // namespace mhd_openhaptics
