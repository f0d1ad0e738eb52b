#pragma once
// The scripted bad stream of dds_test_lossy_publisher: sensor 0 moving smoothly along x
// (p = (0.001 i, 1, 0) m), where sample i is sent as it is or made bad in one way.
// Shared by the publisher and the tests, which expect each bad kind to be dropped.

#include <cstdint>

namespace mhd::dds::test {

enum class LossyKind {
  Good,
  Lost,          ///< never sent (a gap in the sequence; invisible to the subscriber)
  SwappedLate,   ///< sent after sample i + 1: its sequence goes backwards
  Delayed,       ///< measured 0.3 s before it is sent: stale
  NonFinite,     ///< NaN in the position
  OutOfRange,    ///< 1000 m away
  BadQuaternion, ///< norm 2
  Future,        ///< stamped 1 s ahead
  OtherRig,      ///< carries rig_id + 1
};

inline LossyKind lossy_kind(std::uint64_t i) {
  if (i % 10 == 3) return LossyKind::Lost;
  if (i % 10 == 5) return LossyKind::SwappedLate;
  if (i % 10 == 7) return LossyKind::Delayed;
  if (i % 20 == 9) return LossyKind::NonFinite;
  if (i % 20 == 19) return LossyKind::OutOfRange;
  if (i % 40 == 1) return LossyKind::BadQuaternion;
  if (i % 40 == 11) return LossyKind::Future;
  if (i % 40 == 21) return LossyKind::OtherRig;
  return LossyKind::Good;
}

/// The good position's x of sample i.
inline double lossy_x_m(std::uint64_t i) { return 0.001 * static_cast<double>(i); }

}  // namespace mhd::dds::test
