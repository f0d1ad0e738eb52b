#pragma once
// The reaction of the rendered force on the touched objects: the hand is pushed by F, so
// the objects the proxy rests on are pushed by -F, at the proxy. With several constraint
// planes (a box's side and the floor) -F is shared among their objects in proportion to
// the load each plane carries (F's component along its normal), the tangential part
// (friction) going with the load.

#include "proxy/god_object.h"

#include <array>

namespace mhd {

struct ContactReaction {
  int object = -1;
  Eigen::Vector3d f_W_N = Eigen::Vector3d::Zero();  ///< force on the object, at the proxy
};

struct ContactReactions {
  std::array<ContactReaction, kMaxConstraintPlanes> on{};
  int count = 0;  ///< objects pushed; each appears once
};

/// The objects of state's constraint planes and the share of -force_W_N (the force on the
/// hand) each takes; the shares add up to -force_W_N. None without a plane or a force.
/// Allocates nothing.
[[nodiscard]] ContactReactions contact_reactions(const ProxyState& state, const Eigen::Vector3d& force_W_N) noexcept;

}  // namespace mhd
