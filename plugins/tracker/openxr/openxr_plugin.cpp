// The `openxr` tracker: a headset's head pose through the OpenXR loader. A headless
// session (xr_session.h) locates the view space in the base space (stage or local) at
// most rate_hz times a second; each pose that passes head_pose_check.h becomes a sample
// of head_sensor_id in the tracker frame T, which is the OpenXR base space (y up, -z
// forward, metres): the scene's rig places T in the world (its tracker frame). The base
// pose comes from elsewhere (<server> base_pose_source odometry). Nothing is rendered.

#include "head_pose_check.h"
#include "xr_session.h"

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace mhd::openxr {

/// The counters: one per verdict, then the reads that found the session not running.
constexpr std::size_t kCounterCount = kVerdictCounterNames.size() + 1;

class OpenXrTracker {
 public:
  static constexpr std::array kParams{
      sdk::choice("reference_space", "stage|local", "stage",
                  "the OpenXR space the head is located in, the tracker frame: stage (the play area's floor) or "
                  "local (where the headset was at start, eye height)"),
      sdk::integer("head_sensor_id", "", "1", "the sensor id of the head's samples (<server> head_sensor_id)",
                   sdk::between(0, 31)),
      sdk::number("max_position_m", "m", "20", "poses farther out, per coordinate, are refused",
                  sdk::above_up_to(0, 1000)),
      sdk::number("rate_hz", "Hz", "100", "head poses located per second, at most", sdk::between(1, 1000)),
      sdk::text("application_name", "MHD", "the name the OpenXR runtime shows for the session")};

  OpenXrTracker(const mhd_host& host, const sdk::Params& params)
      : host_(host),
        sensor_id_(static_cast<std::uint32_t>(params.integer("head_sensor_id"))),
        max_position_m_(params.number("max_position_m")),
        period_s_(1.0 / params.number("rate_hz")),
        session_(SessionOptions{params.text("application_name"), params.text("reference_space") == "local"
                                                                    ? XR_REFERENCE_SPACE_TYPE_LOCAL
                                                                    : XR_REFERENCE_SPACE_TYPE_STAGE}) {}

  void stop() { session_.end(); }

  /// At most one head pose per period; a lost session or instance is an error that ends
  /// the run (the host stops the base).
  mhd_status tracker_read(std::span<mhd_tracker_sample> out, std::size_t& count) {
    // The runtime is asked nothing between periods: its calls may lock and allocate, and
    // the host's io thread calls this at 1 kHz.
    const double now_s = sdk::host_now(host_);
    if (out.empty() || now_s < next_read_s_) return MHD_NO_DATA;
    next_read_s_ = now_s + period_s_;
    session_.poll_events();
    if (!session_.running()) {
      ++not_running_;
      return MHD_NO_DATA;
    }
    const XrSpaceLocation location = session_.locate_head(session_.now());
    const HeadPoseVerdict verdict = check_head_pose(location, max_position_m_);
    ++counts_[static_cast<std::size_t>(verdict)];
    if (verdict != HeadPoseVerdict::Accepted) return MHD_NO_DATA;
    out[0] = to_sample(location, now_s);
    count = 1;
    return MHD_OK;
  }

  std::size_t counters(std::span<mhd_counter> out) const {
    for (std::size_t i = 0; i < kCounterCount && i < out.size(); ++i) {
      out[i] = i < counts_.size() ? mhd_counter{kVerdictCounterNames[i], counts_[i]}
                                  : mhd_counter{"reads_not_running", not_running_};
    }
    return kCounterCount;
  }

 private:
  /// The located pose as a sample, stamped with the host's time of the read (it was
  /// located for "now"); OpenXR's (x, y, z, w) as (w, x, y, z).
  mhd_tracker_sample to_sample(const XrSpaceLocation& location, double now_s) {
    mhd_tracker_sample s{};
    s.sensor_id = sensor_id_;
    s.sequence = ++sequence_;
    s.timestamp_s = now_s;
    const XrPosef& X_T_head = location.pose;
    s.p_T_m[0] = X_T_head.position.x;
    s.p_T_m[1] = X_T_head.position.y;
    s.p_T_m[2] = X_T_head.position.z;
    s.q_T_wxyz[0] = X_T_head.orientation.w;
    s.q_T_wxyz[1] = X_T_head.orientation.x;
    s.q_T_wxyz[2] = X_T_head.orientation.y;
    s.q_T_wxyz[3] = X_T_head.orientation.z;
    return s;
  }

  mhd_host host_;
  std::uint32_t sensor_id_;
  double max_position_m_;
  double period_s_;
  HeadSession session_;
  double next_read_s_ = 0.0;
  std::uint64_t sequence_ = 0;
  VerdictCounts counts_{};
  std::uint64_t not_running_ = 0;
};

}  // namespace mhd::openxr

MHD_PLUGIN_ENTRY(mhd::openxr::OpenXrTracker,
                 {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                  .description = "A headset's head pose through the OpenXR loader (headless session, no rendering)"})
