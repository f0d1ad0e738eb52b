#pragma once
// The force from touching a replica whose data stopped coming (docs/shared-objects.md):
// the replica then holds the object where it was, while the truth may
// move on, and the correction that comes with the link would carry the hand with it. So,
// as stale tracking does, the force from the replica fades out once its state is older
// than stale_after_s, and fades back in once fresh states come again. The gain moves at
// a bounded rate each way, so it never steps. Allocates nothing.

namespace mhd {

struct ReplicaFadeSettings {
  /// The replica's state is stale beyond this age: the dead-reckoning horizon.
  double stale_after_s = 0.1;
  double fade_out_s = 0.1;  ///< full force to none
  double fade_in_s = 0.3;   ///< none to full force
};

class ReplicaFade {
 public:
  explicit ReplicaFade(const ReplicaFadeSettings& settings = {}) noexcept : settings_(settings) {}

  /// The gain for this tick (dt_s long) with the replica's state age_s old: towards 1
  /// while fresh, towards 0 while stale (a NaN age is stale), at most dt / fade time per
  /// tick. A dt that is not positive and finite changes nothing.
  double update(double age_s, double dt_s) noexcept {
    if (!(dt_s > 0.0) || !(dt_s < 1e3)) return gain_;
    const bool fresh = age_s <= settings_.stale_after_s;
    const double step = fresh ? dt_s / settings_.fade_in_s : -dt_s / settings_.fade_out_s;
    gain_ += step;
    gain_ = gain_ < 0.0 ? 0.0 : (gain_ > 1.0 ? 1.0 : gain_);
    return gain_;
  }
  [[nodiscard]] double gain() const noexcept { return gain_; }

 private:
  ReplicaFadeSettings settings_;
  double gain_ = 1.0;
};

}  // namespace mhd
