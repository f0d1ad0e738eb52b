#include "haptic_server/floor_tracker.h"

#include <algorithm>

namespace mhd {

FloorTracker::FloorTracker(const OtherRigSensorList& sensors) noexcept : sensors_(sensors) {
  sensors_.count = std::min(sensors_.count, kMaxOtherRigs);
  view_.count = sensors_.count;
}

std::optional<FloorSlot> floor_slot_of(const OtherRigSensorList& sensors, std::uint32_t sensor_id) noexcept {
  const std::size_t count = std::min(sensors.count, kMaxOtherRigs);
  for (std::size_t i = 0; i < count; ++i) {
    if (sensors.rigs[i].head_sensor_id == sensor_id) return FloorSlot{i, false};
    if (sensors.rigs[i].base_sensor_id == sensor_id) return FloorSlot{i, true};
  }
  return std::nullopt;
}

void FloorTracker::take(const FloorSlot& slot, double t_s, const Eigen::Vector2d& p_W) noexcept {
  if (slot.rig >= sensors_.count) return;
  TrackedDisc& disc = slot.base ? view_.rigs[slot.rig].base : view_.rigs[slot.rig].user;
  Anchor& anchor = anchors_[slot.rig][slot.base ? 1 : 0];
  if (!disc.known) {
    disc = TrackedDisc{true, t_s, p_W, Eigen::Vector2d::Zero()};
    anchor = Anchor{t_s, p_W};
    return;
  }
  if (!(t_s > disc.t_s)) return;
  const double span_s = t_s - anchor.t_s;
  if (span_s >= kVelocityWindow_s) {
    disc.v_W = (p_W - anchor.p_W) / span_s;
    anchor = Anchor{disc.t_s, disc.p_W};  // the next window starts at the previous sample
  }
  disc.t_s = t_s;
  disc.p_W = p_W;
}

}  // namespace mhd
