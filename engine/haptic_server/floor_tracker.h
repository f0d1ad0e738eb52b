#pragma once
// The io thread's side of the floor view (planner/floor_view.h): which tracker sensors are
// the other rigs' users and bases (<server> other_rig_sensors), and their newest positions
// and velocities from the samples the io thread accepts. The velocity is the displacement
// since an anchor sample at least kVelocityWindow_s older, so tracker noise is not
// differentiated sample to sample. Fixed size; take() neither locks nor allocates.

#include "planner/floor_view.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace mhd {

/// The tracker sensors of one other rig: the one its user wears and the one on its base.
struct OtherRigSensors {
  std::uint32_t head_sensor_id = 0;
  std::uint32_t base_sensor_id = 0;
};

struct OtherRigSensorList {
  std::array<OtherRigSensors, kMaxOtherRigs> rigs{};
  std::size_t count = 0;
};

/// Which disc of the floor view a sensor feeds.
struct FloorSlot {
  std::size_t rig = 0;
  bool base = false;  ///< the rig's base (else its user)
};

/// The slot `sensor_id` feeds in `sensors`, if it is another rig's (the first
/// min(count, kMaxOtherRigs) rigs are looked at).
[[nodiscard]] std::optional<FloorSlot> floor_slot_of(const OtherRigSensorList& sensors,
                                                     std::uint32_t sensor_id) noexcept;

class FloorTracker {
 public:
  static constexpr double kVelocityWindow_s = 0.1;

  explicit FloorTracker(const OtherRigSensorList& sensors) noexcept;

  /// The slot `sensor_id` feeds, if it is another rig's.
  [[nodiscard]] std::optional<FloorSlot> slot_of(std::uint32_t sensor_id) const noexcept {
    return floor_slot_of(sensors_, sensor_id);
  }
  /// An accepted sample of the slot's sensor: the disc's centre on the floor (world x, z),
  /// measured at t_s. An older sample than the newest is ignored.
  void take(const FloorSlot& slot, double t_s, const Eigen::Vector2d& p_W) noexcept;

  [[nodiscard]] const FloorView& view() const noexcept { return view_; }

 private:
  struct Anchor {
    double t_s = 0.0;
    Eigen::Vector2d p_W = Eigen::Vector2d::Zero();
  };
  OtherRigSensorList sensors_;
  FloorView view_;
  std::array<std::array<Anchor, 2>, kMaxOtherRigs> anchors_{};  ///< [rig][user, base]
};

}  // namespace mhd
