// A tracker for the haptic server's fault tests: each read returns one base-sensor sample
// (sensor 0) at the fixed pose given by param pose="px py pz qw qx qy qz" (tracker
// frame, metres), stamped now, then fails as fault_injection.h configures.
#include "fault_injection.h"

#include <cstddef>
#include <cstdio>
#include <span>
#include <stdexcept>

namespace {

class FaultTracker {
 public:
  static constexpr auto kParams = mhd::sdk::join(
      fault_injection::kParams,
      std::array{mhd::sdk::text("pose", nullptr, "px py pz qw qx qy qz, tracker frame")});

  FaultTracker(const mhd_host& host, const mhd::sdk::Params& params) : hardware_(host, params) {
    if (const auto pose = params.optional_text("pose")) {
      double* p = pose_.data();
      if (std::sscanf(pose->c_str(), "%lf %lf %lf %lf %lf %lf %lf", &p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6]) !=
          7) {
        throw mhd::sdk::ParamError("pose needs 7 numbers");
      }
    }
  }

  mhd_status tracker_read(std::span<mhd_tracker_sample> out, std::size_t& count) {
    bool absurd = false;  // a tracker has no absurd value to report: nan and huge read as good
    if (const mhd_status s = hardware_.next_read(absurd); s != MHD_OK) return s;
    if (out.empty()) return MHD_NO_DATA;
    mhd_tracker_sample& sample = out[0];
    sample = {};
    sample.sensor_id = 0;
    sample.sequence = ++sequence_;
    sample.timestamp_s = hardware_.now_s();
    for (int i = 0; i < 3; ++i) sample.p_T_m[i] = pose_[static_cast<std::size_t>(i)];
    for (int i = 0; i < 4; ++i) sample.q_T_wxyz[i] = pose_[static_cast<std::size_t>(3 + i)];
    count = 1;
    return MHD_OK;
  }

 private:
  fault_injection::FaultyHardware hardware_;
  std::array<double, 7> pose_{0, 0, 0, 1, 0, 0, 0};
  std::uint64_t sequence_ = 0;
};

}  // namespace

MHD_PLUGIN_ENTRY(FaultTracker, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                                .description = "test tracker that fails on cue"})
