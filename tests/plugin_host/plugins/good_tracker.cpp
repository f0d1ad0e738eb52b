// A tracker returning two samples per read, with tracker_wait (data is always there, or
// never with no_data) and two counters (reads so far, a fixed 7). Param
// mode=ok|no_data|too_many|bad_quat|nan|bad_counter breaks one call in one way.
#include <mhd/plugin_sdk.hpp>

#include <array>
#include <limits>
#include <span>
#include <string>

namespace {

enum class Mode { Ok, NoData, TooMany, BadQuat, Nan, BadCounter };

class Tracker {
 public:
  static constexpr std::array kParams{mhd::sdk::text("mode", nullptr, "how tracker_read misbehaves")};

  explicit Tracker(const mhd::sdk::Params& params) {
    const std::string m = params.optional_text("mode").value_or("ok");
    mode_ = m == "no_data"       ? Mode::NoData
            : m == "too_many"    ? Mode::TooMany
            : m == "bad_quat"    ? Mode::BadQuat
            : m == "nan"         ? Mode::Nan
            : m == "bad_counter" ? Mode::BadCounter
                                 : Mode::Ok;
  }

  std::size_t tracker_read(std::span<mhd_tracker_sample> out) {
    ++reads_;
    if (mode_ == Mode::NoData) return 0;
    std::size_t n = 0;
    for (; n < 2 && n < out.size(); ++n) {
      mhd_tracker_sample& s = out[n];
      s = mhd_tracker_sample{};
      s.sensor_id = static_cast<uint32_t>(n);
      s.sequence = ++sequence_;
      s.timestamp_s = 1.0;
      s.p_T_m[0] = 0.1 * static_cast<double>(n);
      s.q_T_wxyz[0] = 1.0;
    }
    if (mode_ == Mode::BadQuat && n > 0) out[0].q_T_wxyz[0] = 2.0;
    if (mode_ == Mode::Nan && n > 1) out[1].p_T_m[2] = std::numeric_limits<double>::quiet_NaN();
    // A count above capacity: the SDK passes it on, the host must refuse it.
    return mode_ == Mode::TooMany ? out.size() + 1 : n;
  }

  mhd_status tracker_wait(double /*timeout_s*/) const { return mode_ == Mode::NoData ? MHD_NO_DATA : MHD_OK; }

  std::size_t counters(std::span<mhd_counter> out) const {
    const std::array<mhd_counter, 2> all{
        {{"reads", reads_}, {mode_ == Mode::BadCounter ? "has space" : "dropped_test", 7}}};
    for (std::size_t i = 0; i < all.size() && i < out.size(); ++i) out[i] = all[i];
    return all.size();
  }

 private:
  Mode mode_ = Mode::Ok;
  uint64_t sequence_ = 0;
  uint64_t reads_ = 0;
};

}  // namespace

MHD_PLUGIN_ENTRY(Tracker, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "0.1.0", .description = nullptr})
