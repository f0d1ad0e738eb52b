// cpp_contact_log: an MHD display plugin in C++20 on the installed plugin SDK
// (<mhd/plugin_sdk.hpp>), built out of tree. From the frames the host gives it, it counts
// the contacts (a frame in contact after one that was not) and keeps the largest force
// magnitude; on stop it prints to stderr
//   cpp_contact_log: <N> frames, <C> contacts, max force <F> N
// Parameter: min_force_N (default 0): a contact counts only once the force reaches it.

#include <mhd/plugin_sdk.hpp>

#include <array>
#include <cmath>
#include <cstdio>

namespace {

class ContactLog {
 public:
  // Declared for the host, which checks a scene's parameters before open().
  static constexpr std::array kParams{
      mhd::sdk::number("min_force_N", "N", "0", "a contact counts only once the force reaches this",
                       mhd::sdk::non_negative()),
  };

  explicit ContactLog(const mhd::sdk::Params& params) : min_force_N_(params.number("min_force_N")) {}

  void stop() const {
    std::fprintf(stderr, "%s: %llu frames, %llu contacts, max force %.3f N\n", MHD_PLUGIN_NAME, frames_, contacts_,
                 max_force_N_);
  }

  void display_write(const mhd_display_frame& frame) {
    ++frames_;
    const double force_N = std::hypot(frame.force_W_N[0], frame.force_W_N[1], frame.force_W_N[2]);
    if (force_N > max_force_N_) max_force_N_ = force_N;
    const bool touching = frame.in_contact != 0 && force_N >= min_force_N_;
    if (touching && !touching_) ++contacts_;
    touching_ = touching;
  }

 private:
  double min_force_N_;
  unsigned long long frames_ = 0;
  unsigned long long contacts_ = 0;
  bool touching_ = false;
  double max_force_N_ = 0.0;
};

}  // namespace

MHD_PLUGIN_ENTRY(ContactLog, {.kind = MHD_PLUGIN_KIND, .name = MHD_PLUGIN_NAME, .version = "1.0.0",
                              .description = "Counts contacts and the largest force (C++ example, built out of tree)"})
