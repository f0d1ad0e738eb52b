// A link that hands back, on the next link_read, every message sent to it, with its
// rig id raised by 1 (as if the other rig had sent it); counter "sent". Param
// mode=ok|nan|bad_quat|bad_kind|too_many breaks link_read in one way.
#include <mhd/plugin_sdk.hpp>

#include <array>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace {

class Link {
 public:
  static constexpr std::array kParams{mhd::sdk::text("mode", nullptr, "how link_read misbehaves")};

  explicit Link(const mhd::sdk::Params& params) : mode_(params.optional_text("mode").value_or("ok")) {}

  void link_send(std::span<const mhd_link_message> messages) {
    for (const mhd_link_message& m : messages) {
      back_.push_back(m);
      ++back_.back().rig_id;
      ++sent_;
    }
  }

  std::size_t link_read(std::span<mhd_link_message> out) {
    std::size_t n = 0;
    for (; n < back_.size() && n < out.size(); ++n) out[n] = back_[n];
    back_.erase(back_.begin(), back_.begin() + static_cast<std::ptrdiff_t>(n));
    if (n > 0 && mode_ == "nan") out[0].f_W_N[1] = std::numeric_limits<double>::quiet_NaN();
    if (n > 0 && mode_ == "bad_quat") out[0].q_W_wxyz[0] = 2.0;
    if (n > 0 && mode_ == "bad_kind") out[0].kind = 9;
    // A count above capacity: the SDK passes it on, the host must refuse it.
    return mode_ == "too_many" ? out.size() + 1 : n;
  }

  std::size_t counters(std::span<mhd_counter> out) const {
    if (!out.empty()) out[0] = {"sent", sent_};
    return 1;
  }

 private:
  std::string mode_;
  std::vector<mhd_link_message> back_;
  uint64_t sent_ = 0;
};

}  // namespace

MHD_PLUGIN_ENTRY(Link, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "0.1.0", .description = nullptr})
