#pragma once
// The user's head as the tracker last measured it, in the world, and its hand-off from
// the io thread (one writer) to the planner, display and recorder threads (readers): a
// seqlock, so the io thread neither locks nor allocates to publish it.

#include "realtime/seqlock.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>

namespace mhd {

struct HeadState {
  bool known = false;  ///< a head sample has arrived
  double t_s = 0.0;    ///< when it was measured, host clock
  Eigen::Vector3d p_W_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_W = Eigen::Quaterniond::Identity();
};

class SharedHead {
 public:
  SharedHead() noexcept : values_(pack(HeadState{})) {}

  /// The io thread only.
  void set(const HeadState& h) noexcept { values_.write(pack(h)); }

  /// Any thread; never waits for the writer.
  [[nodiscard]] HeadState get() const noexcept {
    const std::array<double, 9> v = values_.read();
    HeadState h;
    h.known = v[0] != 0.0;
    h.t_s = v[1];
    h.p_W_m = Eigen::Vector3d(v[2], v[3], v[4]);
    h.q_W = Eigen::Quaterniond(v[5], v[6], v[7], v[8]);
    return h;
  }

 private:
  static std::array<double, 9> pack(const HeadState& h) noexcept {
    return {h.known ? 1.0 : 0.0, h.t_s,        h.p_W_m.x(), h.p_W_m.y(), h.p_W_m.z(),
            h.q_W.w(),           h.q_W.x(),    h.q_W.y(),   h.q_W.z()};
  }

  realtime::Seqlock<9> values_;
};

}  // namespace mhd
