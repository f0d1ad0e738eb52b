#pragma once
// The user's head as the tracker last measured it, in the world: what the io thread hands
// to the planner, display and recorder threads.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mhd {

struct HeadState {
  bool known = false;  ///< a head sample has arrived
  double t_s = 0.0;    ///< when it was measured, host clock
  Eigen::Vector3d p_W_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_W = Eigen::Quaterniond::Identity();
};

}  // namespace mhd
