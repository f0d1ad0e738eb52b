#pragma once
// What rigs sharing a pushable object tell each other (docs/shared-objects.md). The
// object's authority (one rig) runs its physics and sends its state; every other rig
// renders a replica of that state and sends the authority its user's push. Times are on
// the clock all rigs share (the tracker's, NTP/PTP-synchronised), in seconds.

#include "geometry/pose.h"
#include "proxy/object_twist.h"

#include <Eigen/Core>

#include <cstdint>

namespace mhd {

/// The authority's state of one shared object at t_s.
struct SharedObjectState {
  int object = -1;
  std::uint32_t authority_rig = 0;
  /// The authority's term: each hand-over starts a higher one, so a rig that lost the
  /// authority is recognised by its older term, whatever its clock or sequence says.
  std::uint32_t epoch = 0;
  std::uint64_t sequence = 0;  ///< increasing within one term
  double t_s = 0.0;
  Pose X_WO = Pose::Identity();
  ObjectTwist twist_W;
};

/// One rig's push on a shared object at t_s: the reaction of the force its user's hand
/// feels, acting at a point given in the object's own frame (the object moves between
/// sender and authority; the material point pushed does not).
struct SharedPush {
  int object = -1;
  std::uint32_t from_rig = 0;
  std::uint64_t sequence = 0;  ///< increasing per sending rig
  double t_s = 0.0;
  Eigen::Vector3d f_W_N = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_O_m = Eigen::Vector3d::Zero();
};

}  // namespace mhd
