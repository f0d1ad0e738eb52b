#pragma once
// Plays recorded tracker samples on the host clock: a sample recorded at t_rec is
// released at t_start + (t_rec - t_first), t_first being the first sample's recorded
// time, and carries that host time as its timestamp. Sensor ids, sequence numbers and
// poses are passed through as recorded.

#include <mhd/plugin_abi.h>

#include <cstddef>
#include <span>
#include <vector>

namespace mhd::tracker_replay {

/// Not thread-safe.
class ReplayModel {
 public:
  /// Precondition: samples non-empty, timestamps non-decreasing (read_replay_csv checks).
  explicit ReplayModel(std::vector<mhd_tracker_sample> samples);

  /// Plays from the first sample, which is due at t_s.
  void start(double t_s);

  /// Moves the samples due by now_s (and not read yet) into out, in file order;
  /// returns how many. Precondition: started.
  std::size_t read(double now_s, std::span<mhd_tracker_sample> out);

  [[nodiscard]] bool finished() const { return next_ == samples_.size(); }
  [[nodiscard]] std::size_t size() const { return samples_.size(); }

 private:
  std::vector<mhd_tracker_sample> samples_;
  std::size_t next_ = 0;
  double offset_s_ = 0.0;  ///< host time minus recorded time
};

}  // namespace mhd::tracker_replay
