#include "replay_model.h"

#include <stdexcept>
#include <utility>

namespace mhd::tracker_replay {

ReplayModel::ReplayModel(std::vector<mhd_tracker_sample> samples) : samples_(std::move(samples)) {
  if (samples_.empty()) throw std::invalid_argument("a replay needs at least one sample");
}

void ReplayModel::start(double t_s) {
  next_ = 0;
  offset_s_ = t_s - samples_.front().timestamp_s;
}

std::size_t ReplayModel::read(double now_s, std::span<mhd_tracker_sample> out) {
  constexpr double kTimeTolerance_s = 1e-9;  // t_rec + (t_start - t_first) may round past t_start
  std::size_t n = 0;
  while (n < out.size() && next_ < samples_.size() &&
         samples_[next_].timestamp_s + offset_s_ <= now_s + kTimeTolerance_s) {
    out[n] = samples_[next_++];
    out[n].timestamp_s += offset_s_;
    ++n;
  }
  return n;
}

}  // namespace mhd::tracker_replay
