// A link for the haptic server's tests: each read brings one state of shared object 1
// from rig 1, its authority, moving from start_m at velocity_mps since the plugin
// started, stamped now; then it fails as fault_injection.h configures (nan: a state
// whose position is NaN). Every message sent to it is counted (counter "sent").
#include "fault_injection.h"

#include <array>
#include <cstddef>
#include <cstdio>
#include <span>
#include <string>

namespace {

std::array<double, 3> three(const mhd::sdk::Params& params, const char* name) {
  std::array<double, 3> v{};
  if (const auto text = params.optional_text(name)) {
    if (std::sscanf(text->c_str(), "%lf %lf %lf", &v[0], &v[1], &v[2]) != 3) {
      throw mhd::sdk::ParamError(std::string(name) + " needs 3 numbers");
    }
  }
  return v;
}

class FaultLink {
 public:
  static constexpr auto kParams = mhd::sdk::join(
      fault_injection::kParams,
      std::array{mhd::sdk::text("start_m", nullptr, "the object's origin at the start, x y z"),
                 mhd::sdk::text("velocity_mps", nullptr, "its velocity, x y z")});

  FaultLink(const mhd_host& host, const mhd::sdk::Params& params)
      : hardware_(host, params), start_m_(three(params, "start_m")), velocity_mps_(three(params, "velocity_mps")) {}

  void start() { t0_s_ = hardware_.now_s(); }

  void link_send(std::span<const mhd_link_message> messages) { sent_ += messages.size(); }

  mhd_status link_read(std::span<mhd_link_message> out, std::size_t& count) {
    bool absurd = false;
    if (const mhd_status s = hardware_.next_read(absurd); s != MHD_OK) return s;
    if (out.empty()) return MHD_NO_DATA;
    const double t_s = hardware_.now_s();
    mhd_link_message& m = out[0];
    m = {};
    m.kind = MHD_LINK_STATE;
    m.object_id = 1;
    m.rig_id = 1;
    m.sequence = ++sequence_;
    m.timestamp_s = t_s;
    for (std::size_t i = 0; i < 3; ++i) {
      m.p_W_m[i] = start_m_[i] + velocity_mps_[i] * (t_s - t0_s_);
      m.v_W_mps[i] = velocity_mps_[i];
    }
    if (absurd) m.p_W_m[0] = hardware_.absurd();
    m.q_W_wxyz[0] = 1.0;
    count = 1;
    return MHD_OK;
  }

  std::size_t counters(std::span<mhd_counter> out) const {
    if (!out.empty()) out[0] = {"sent", sent_};
    return 1;
  }

 private:
  fault_injection::FaultyHardware hardware_;
  std::array<double, 3> start_m_, velocity_mps_;
  double t0_s_ = 0.0;
  std::uint64_t sequence_ = 0, sent_ = 0;
};

}  // namespace

MHD_PLUGIN_ENTRY(FaultLink, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                             .description = "test link that plays an authority's states and fails on cue"})
