// The simulated device behind vendor_sdk.h: the handle sits where the hand's spring
// balances the rendered force; the vendor's watchdog drops a force older than its timeout.
#include "vendor_sdk.h"

#include <chrono>
#include <cmath>
#include <cstring>
#include <new>

struct vc_device {
  double rest_mm[3] = {10.0, 20.0, 30.0};
  double force_N[3] = {0.0, 0.0, 0.0};
  std::chrono::steady_clock::time_point force_time{};
  std::chrono::milliseconds watchdog{10};
  bool enabled = false;
};

namespace {

constexpr double kHandCompliance_mm_per_N = 2.0;
constexpr double kMaxForce_N = 5.0;

/// The force the motors render now: none when disabled or when the watchdog has fired.
double rendered_force_N(const vc_device& d, int axis) {
  const bool fresh = std::chrono::steady_clock::now() - d.force_time <= d.watchdog;
  return d.enabled && fresh ? d.force_N[axis] : 0.0;
}

}  // namespace

extern "C" {

int vc_open(const char* serial, vc_device** out) {
  if (serial == nullptr || out == nullptr) return VC_ERR_BAD_ARGUMENT;
  if (std::strncmp(serial, "SIM-", 4) != 0) return VC_ERR_NO_DEVICE;
  *out = new (std::nothrow) vc_device;
  return *out != nullptr ? VC_OK : VC_ERR_NO_DEVICE;
}

void vc_close(vc_device* device) { delete device; }

const char* vc_error_string(int code) {
  switch (code) {
    case VC_OK: return "no error";
    case VC_ERR_NO_DEVICE: return "no device with that serial number";
    case VC_ERR_BAD_ARGUMENT: return "bad argument";
    case VC_ERR_FORCE_LIMIT: return "force above the device's limit";
    default: return "unknown error";
  }
}

int vc_set_watchdog_ms(vc_device* device, unsigned ms) {
  if (device == nullptr || ms == 0) return VC_ERR_BAD_ARGUMENT;
  device->watchdog = std::chrono::milliseconds(ms);
  return VC_OK;
}

int vc_enable_forces(vc_device* device, int on) {
  if (device == nullptr) return VC_ERR_BAD_ARGUMENT;
  device->enabled = on != 0;
  return VC_OK;
}

double vc_max_force_N(const vc_device* /*device*/) { return kMaxForce_N; }
double vc_max_stiffness_N_per_mm(const vc_device* /*device*/) { return 2.5; }

int vc_get_workspace_mm(const vc_device* device, double min_mm[3], double max_mm[3]) {
  if (device == nullptr || min_mm == nullptr || max_mm == nullptr) return VC_ERR_BAD_ARGUMENT;
  for (int i = 0; i < 3; ++i) {
    min_mm[i] = device->rest_mm[i] - 80.0;
    max_mm[i] = device->rest_mm[i] + 80.0;
  }
  return VC_OK;
}

int vc_get_position_mm(vc_device* device, double p_mm[3]) {
  if (device == nullptr || p_mm == nullptr) return VC_ERR_BAD_ARGUMENT;
  for (int i = 0; i < 3; ++i) p_mm[i] = device->rest_mm[i] + kHandCompliance_mm_per_N * rendered_force_N(*device, i);
  return VC_OK;
}

int vc_get_velocity_mm_s(vc_device* device, double v_mm_s[3]) {
  if (device == nullptr || v_mm_s == nullptr) return VC_ERR_BAD_ARGUMENT;
  for (int i = 0; i < 3; ++i) v_mm_s[i] = 0.0;  // the simulated hand settles at once
  return VC_OK;
}

unsigned vc_get_buttons(const vc_device* /*device*/) { return 0u; }

int vc_set_force_N(vc_device* device, const double force_N[3]) {
  if (device == nullptr || force_N == nullptr) return VC_ERR_BAD_ARGUMENT;
  const double norm_N = std::sqrt(force_N[0] * force_N[0] + force_N[1] * force_N[1] + force_N[2] * force_N[2]);
  if (!(norm_N <= kMaxForce_N)) return VC_ERR_FORCE_LIMIT;
  for (int i = 0; i < 3; ++i) device->force_N[i] = force_N[i];
  device->force_time = std::chrono::steady_clock::now();
  return VC_OK;
}

}  // extern "C"
