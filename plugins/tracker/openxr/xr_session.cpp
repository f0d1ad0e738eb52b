#include "xr_session.h"

#include "xr_result_name.h"
#include "xr_struct.h"

#include <dlfcn.h>
#include <stdlib.h>
#include <time.h>

#define XR_USE_TIMESPEC  // xrConvertTimespecTimeToTimeKHR
#include <openxr/openxr_platform.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace mhd::openxr {
namespace {

constexpr const char* kNoRuntimeAdvice =
    "install an OpenXR runtime such as Monado and make it active, or set XR_RUNTIME_JSON to its manifest "
    "(docs/hardware.md)";

/// Keeps the loader loaded for the rest of the process, whatever becomes of the plugin.
/// Debian's loader (1.0.20) leaks its bookkeeping of each instance (about 1.3 KiB); a
/// loader unloaded with the plugin would leave that leak to an unnamed module, which
/// LeakSanitizer's suppression of the loader (tools/ci/lsan.supp) cannot match.
void pin_loader() noexcept {
  Dl_info loader{};
  if (dladdr(reinterpret_cast<void*>(&xrCreateInstance), &loader) != 0 && loader.dli_fname != nullptr) {
    (void)dlopen(loader.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
  }
}

/// Throws "<what>: <advice>" when `result` failed.
void require(XrResult result, const std::string& what, const char* advice) {
  if (XR_FAILED(result)) throw std::runtime_error(what + "; " + advice);
}

}  // namespace

HeadSession::HeadSession(const SessionOptions& options) {
  try {
    create_instance(options);
    create_session_and_spaces(options.base_space);
  } catch (...) {
    release();
    throw;
  }
}

HeadSession::~HeadSession() {
  end();
  release();
}

void HeadSession::create_instance(const SessionOptions& options) {
  // Headless: a session with no graphics binding, for the head pose alone.
  const std::array<const char*, 2> extensions{XR_MND_HEADLESS_EXTENSION_NAME,
                                              XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME};
  auto info = xr_struct<XrInstanceCreateInfo>(XR_TYPE_INSTANCE_CREATE_INFO);
  const std::size_t n = std::min(options.application_name.size(), sizeof(info.applicationInfo.applicationName) - 1);
  std::memcpy(info.applicationInfo.applicationName, options.application_name.data(), n);
  std::memcpy(info.applicationInfo.engineName, "MHD", 4);
  info.applicationInfo.applicationVersion = 1;
  info.applicationInfo.engineVersion = 1;
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.enabledExtensionNames = extensions.data();
  // The loader writes its own error lines to stderr before the plugin's one line, which
  // names the cause; a user who sets XR_LOADER_DEBUG (error, info, all) sees them again.
  ::setenv("XR_LOADER_DEBUG", "none", 0);
  pin_loader();
  const XrResult r = xrCreateInstance(&info, &instance_);
  if (means_no_runtime(r)) {
    throw std::runtime_error("no OpenXR runtime (xrCreateInstance: " + result_name(r) + "): " + kNoRuntimeAdvice);
  }
  require(r, said("xrCreateInstance", r),
          r == XR_ERROR_EXTENSION_NOT_PRESENT
              ? "the runtime lacks XR_MND_headless or XR_KHR_convert_timespec_time: use one with headless sessions, "
                "such as Monado"
              : "is the OpenXR runtime working? (docs/hardware.md)");
  XrResult f = xrGetInstanceProcAddr(instance_, "xrConvertTimespecTimeToTimeKHR", &convert_timespec_);
  require(f, said("xrGetInstanceProcAddr(xrConvertTimespecTimeToTimeKHR)", f), "the runtime lacks the extension");

  auto system = xr_struct<XrSystemGetInfo>(XR_TYPE_SYSTEM_GET_INFO);
  system.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  const XrResult s = xrGetSystem(instance_, &system, &system_);
  require(s, said("xrGetSystem (head-mounted display)", s),
          s == XR_ERROR_FORM_FACTOR_UNAVAILABLE ? "the runtime sees no headset: is the headset plugged in and on?"
                                                : "is the OpenXR runtime working? (docs/hardware.md)");
}

void HeadSession::create_session_and_spaces(XrReferenceSpaceType base_space) {
  auto session = xr_struct<XrSessionCreateInfo>(XR_TYPE_SESSION_CREATE_INFO);
  session.systemId = system_;  // next NULL: no graphics binding (XR_MND_headless)
  const XrResult s = xrCreateSession(instance_, &session, &session_);
  require(s, said("xrCreateSession (headless)", s), "is the headset in use by another program?");

  auto space = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
  space.poseInReferenceSpace.orientation.w = 1.0f;
  space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  const XrResult v = xrCreateReferenceSpace(session_, &space, &view_);
  require(v, said("xrCreateReferenceSpace (view)", v), "is the OpenXR runtime working? (docs/hardware.md)");
  space.referenceSpaceType = base_space;
  const XrResult b = xrCreateReferenceSpace(session_, &space, &base_);
  require(b, said(base_space == XR_REFERENCE_SPACE_TYPE_STAGE ? "xrCreateReferenceSpace (stage)"
                                                              : "xrCreateReferenceSpace (local)",
                  b),
          "set up the play area in the runtime, or use reference_space local");
}

void HeadSession::poll_events() {
  for (;;) {
    auto event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    const XrResult r = xrPollEvent(instance_, &event);
    if (r == XR_EVENT_UNAVAILABLE) return;
    require(r, said("xrPollEvent", r), "the OpenXR runtime failed");
    if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) {
      throw std::runtime_error("the OpenXR instance is being lost (XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING): "
                               "the runtime is shutting down or restarting");
    }
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      on_state(reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state);
    }
  }
}

void HeadSession::on_state(XrSessionState state) {
  state_ = state;
  if (state == XR_SESSION_STATE_READY && !running_) {
    auto begin = xr_struct<XrSessionBeginInfo>(XR_TYPE_SESSION_BEGIN_INFO);
    begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;  // ignored headless
    const XrResult r = xrBeginSession(session_, &begin);
    require(r, said("xrBeginSession", r), "the OpenXR runtime refused to begin the session");
    running_ = true;
  } else if (state == XR_SESSION_STATE_STOPPING && running_) {
    // The runtime stops us (another program took the headset): no head, so the base stops.
    running_ = false;
    (void)xrEndSession(session_);
  } else if (state == XR_SESSION_STATE_LOSS_PENDING) {
    throw std::runtime_error("the OpenXR session is being lost (XR_SESSION_STATE_LOSS_PENDING): the runtime lost "
                             "the headset: is it still plugged in?");
  } else if (state == XR_SESSION_STATE_EXITING) {
    throw std::runtime_error("the OpenXR runtime ended the session (XR_SESSION_STATE_EXITING)");
  }
}

XrTime HeadSession::now() const {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  XrTime t = 0;
  const auto convert = reinterpret_cast<PFN_xrConvertTimespecTimeToTimeKHR>(convert_timespec_);
  const XrResult r = convert(instance_, &ts, &t);
  require(r, said("xrConvertTimespecTimeToTimeKHR", r), "the OpenXR runtime failed");
  return t;
}

XrSpaceLocation HeadSession::locate_head(XrTime t) const {
  auto location = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
  const XrResult r = xrLocateSpace(view_, base_, t, &location);
  if (r == XR_ERROR_SESSION_LOST || r == XR_ERROR_INSTANCE_LOST) {
    throw std::runtime_error("xrLocateSpace: " + result_name(r) + ": the OpenXR runtime lost the headset: is it "
                             "still plugged in?");
  }
  require(r, said("xrLocateSpace", r), "the OpenXR runtime failed");
  return location;
}

void HeadSession::end() noexcept {
  if (!running_) return;
  // The orderly way: ask, wait for STOPPING, end. A runtime that does not answer within
  // a few ms is ended anyway: the session is destroyed next, whatever its state.
  (void)xrRequestExitSession(session_);
  for (int i = 0; i < 50 && state_ != XR_SESSION_STATE_STOPPING; ++i) {
    auto event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    if (xrPollEvent(instance_, &event) == XR_SUCCESS) {
      if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
        state_ = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state;
      }
      continue;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  (void)xrEndSession(session_);
  running_ = false;
}

void HeadSession::release() noexcept {
  if (base_ != XR_NULL_HANDLE) (void)xrDestroySpace(base_);
  if (view_ != XR_NULL_HANDLE) (void)xrDestroySpace(view_);
  if (session_ != XR_NULL_HANDLE) (void)xrDestroySession(session_);
  if (instance_ != XR_NULL_HANDLE) (void)xrDestroyInstance(instance_);
  base_ = view_ = XR_NULL_HANDLE;
  session_ = XR_NULL_HANDLE;
  instance_ = XR_NULL_HANDLE;
}

std::string HeadSession::said(const char* call, XrResult result) const {
  std::array<char, XR_MAX_RESULT_STRING_SIZE> words{};
  if (instance_ != XR_NULL_HANDLE && XR_SUCCEEDED(xrResultToString(instance_, result, words.data()))) {
    return std::string(call) + ": " + words.data();
  }
  return std::string(call) + ": " + result_name(result);
}

}  // namespace mhd::openxr
