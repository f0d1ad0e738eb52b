#pragma once
// One headless OpenXR session through the loader: the instance (XR_MND_headless, no
// graphics binding; XR_KHR_convert_timespec_time for "now"), the head-mounted display's
// system, the session and two reference spaces, VIEW (the head) and the base space the
// head is located in. Every failure is a std::runtime_error of one line naming the call,
// the result and what to do.

#include <openxr/openxr.h>

#include <string>

namespace mhd::openxr {

/// What the session is for and where the head is located.
struct SessionOptions {
  std::string application_name;
  XrReferenceSpaceType base_space = XR_REFERENCE_SPACE_TYPE_STAGE;
};

class HeadSession {
 public:
  explicit HeadSession(const SessionOptions& options);
  ~HeadSession();  ///< ends the session if it runs, then destroys spaces, session, instance
  HeadSession(const HeadSession&) = delete;
  HeadSession& operator=(const HeadSession&) = delete;

  /// Handles the runtime's queued events without waiting: begins the session when it is
  /// ready, ends it when the runtime stops it. Throws when the session or the instance is
  /// being lost or the runtime makes the session exit.
  void poll_events();
  [[nodiscard]] bool running() const noexcept { return running_; }

  /// The runtime's time now (CLOCK_MONOTONIC converted).
  [[nodiscard]] XrTime now() const;

  /// The head (the view space) in the base space at `t`. Throws on a lost session or
  /// instance and on any other failed call; an untracked head is a location, not a throw.
  [[nodiscard]] XrSpaceLocation locate_head(XrTime t) const;

  /// Asks the runtime to stop the session and ends it (waits a few ms for its answer).
  void end() noexcept;

 private:
  void create_instance(const SessionOptions& options);
  void create_session_and_spaces(XrReferenceSpaceType base_space);
  void on_state(XrSessionState state);
  void release() noexcept;
  /// "<call>: <result name>" for a message; the runtime's words when an instance exists.
  [[nodiscard]] std::string said(const char* call, XrResult result) const;

  XrInstance instance_ = XR_NULL_HANDLE;
  XrSystemId system_ = XR_NULL_SYSTEM_ID;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace view_ = XR_NULL_HANDLE;
  XrSpace base_ = XR_NULL_HANDLE;
  PFN_xrVoidFunction convert_timespec_ = nullptr;  ///< xrConvertTimespecTimeToTimeKHR
  XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
  bool running_ = false;  ///< between xrBeginSession and xrEndSession
};

}  // namespace mhd::openxr
