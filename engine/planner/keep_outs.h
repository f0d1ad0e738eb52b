#pragma once
// Everything else on the floor that a base must keep out of: the other users and the other
// bases of a shared world, as the shared tracking sees them. The rig's own user is not one
// of these (PlannerInput::user_W); a one-rig scene has none.
//
// A keep-out is a disc: the base (a disc of the planner's robot radius) may not move
// nearer its centre than robot radius + its radius (+ the safety margin, the band) by its
// own motion. Fixed capacity, so that the planner thread fills and reads it without
// allocating. Planar: 2-vectors are world (x, z).

#include "kinematics/base_pose.h"
#include "planner/planner_settings.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace mhd {

enum class KeepOutKind {
  User,  ///< another rig's user: radius = the human radius
  Base,  ///< another rig's base: radius = that base's robot radius
};

struct KeepOut {
  KeepOutKind kind = KeepOutKind::User;
  Eigen::Vector2d centre_W = Eigen::Vector2d::Zero();
  double radius_m = 0.0;
};

class KeepOuts {
 public:
  static constexpr std::size_t kCapacity = 16;

  /// False (and nothing added) when full.
  bool add(const KeepOut& keep_out) noexcept {
    if (count_ == kCapacity) return false;
    items_[count_++] = keep_out;
    return true;
  }
  void clear() noexcept { count_ = 0; }
  [[nodiscard]] std::size_t size() const noexcept { return count_; }
  [[nodiscard]] bool empty() const noexcept { return count_ == 0; }
  [[nodiscard]] const KeepOut* begin() const noexcept { return items_.data(); }
  [[nodiscard]] const KeepOut* end() const noexcept { return items_.data() + count_; }

 private:
  std::array<KeepOut, kCapacity> items_{};
  std::size_t count_ = 0;
};

/// The distance from the base's centre to a keep-out's centre that the base's own motion
/// may not cross: robot radius + the keep-out's radius.
[[nodiscard]] double contact_distance_m(const KeepOut& keep_out, const PlannerSettings& settings) noexcept;

/// Whether `p` is farther than band + `extra_m` from every keep-out.
[[nodiscard]] bool outside_bands(const KeepOuts& keep_outs, const Eigen::Vector2d& p, double extra_m,
                                 const PlannerSettings& settings) noexcept;

/// Whether the chord from `from` to `to` keeps every keep-out's band (contact distance +
/// safety margin), or, for one the base is already inside, comes no nearer than it is.
[[nodiscard]] bool chord_clears(const KeepOuts& keep_outs, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                const PlannerSettings& settings) noexcept;

/// The planners' last step: planner_geometry::guard_velocity for the rig's own user (band
/// `own_band_m`) and then for every keep-out (band: contact distance + safety margin);
/// inside a keep-out's band the base also backs out of it, at (band - distance) over four
/// periods (a keep-out is seen late and moves: two bases resting at each other's band would
/// turn any error in what each sees of the other into a contact).
/// With keep-outs, the guards of two discs can undo each other, so the arc the base would
/// then drive over one period (body_twist, integrate_twist) is checked against every disc,
/// the own user's included: if it comes nearer than the contact distance (or, from inside,
/// nearer than it starts), the linear velocity becomes zero, which moves the base into none.
/// Without keep-outs this is exactly the one-rig guard. Returns true when v_W changed.
bool guard_keep_outs(const BasePose& base, const Eigen::Vector2d& user, double own_band_m, const KeepOuts& keep_outs,
                     const PlannerSettings& settings, double omega_radps, Eigen::Vector2d& v_W) noexcept;

}  // namespace mhd
