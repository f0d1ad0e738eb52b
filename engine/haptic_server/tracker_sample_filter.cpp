#include "haptic_server/tracker_sample_filter.h"

#include "haptic_server/physical_range.h"

#include <Eigen/Core>

namespace mhd {

const char* to_string(TrackerSampleVerdict verdict) noexcept {
  switch (verdict) {
    case TrackerSampleVerdict::Accepted: return "accepted";
    case TrackerSampleVerdict::SequenceBackwards: return "sequence backwards";
    case TrackerSampleVerdict::FromTheFuture: return "from the future";
    case TrackerSampleVerdict::UnknownSensor: return "unknown sensor";
    case TrackerSampleVerdict::ImplausiblePosition: return "implausible position";
  }
  return "?";
}

std::optional<std::size_t> TrackerSampleFilter::slot_of(std::uint32_t sensor_id) const noexcept {
  if (sensor_id == settings_.base_sensor_id) return 0;
  if (sensor_id == settings_.head_sensor_id) return 1;
  if (const std::optional<FloorSlot> other = floor_slot_of(settings_.other_rigs, sensor_id))
    return 2 + 2 * other->rig + (other->base ? 1 : 0);
  return std::nullopt;
}

TrackerSampleVerdict TrackerSampleFilter::check(const TrackerSample& sample, double read_at_s) {
  const std::optional<std::size_t> slot = slot_of(sample.sensor_id);
  if (!slot) return TrackerSampleVerdict::UnknownSensor;
  SensorTrack& track = sensors_[*slot];
  const bool first = !track.seen;
  if (first) track = {true, sample.sequence, read_at_s};
  const bool restarted = read_at_s - track.accepted_at_s > settings_.sequence_restart_after_s;
  if (sample.timestamp_s > read_at_s + settings_.future_slack_s) return TrackerSampleVerdict::FromTheFuture;
  if (!first && !restarted && sample.sequence <= track.sequence) return TrackerSampleVerdict::SequenceBackwards;
  if (!tracked_position_plausible(Eigen::Vector3d(sample.p_T_m[0], sample.p_T_m[1], sample.p_T_m[2]),
                                  settings_.tracking_range_m)) {
    return TrackerSampleVerdict::ImplausiblePosition;
  }
  track = {true, sample.sequence, read_at_s};
  return TrackerSampleVerdict::Accepted;
}

}  // namespace mhd
