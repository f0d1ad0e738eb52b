#pragma once
// Simulation only: one rig's simulated world shared over DDS (mhd_dds::SimWorld). The
// haptic server's simulated plugins own the world (its simulated user and base move it); its `dds` tracker,
// asked with publish_sim_world, publishes the truth every io tick, and `mhd
// tracker-server --shared-world` writes the newest into its own world before its
// simulated tracker measures it, so the tracker sees the base the haptic server moves,
// as a real tracker sees the real base. Both sides work on the simulated plugins' shared
// world (libs/sim_world), never on the host.

#include "dds_common/dds_topics.h"

#include "simulation/simulated_world.h"

#include <cstdint>

namespace mhd::dds {

/// The truth of `world` now, numbered and stamped.
[[nodiscard]] mhd_dds_SimWorld sim_world_sample(const simulation::SimulatedWorld& world, std::uint32_t rig_id,
                                                std::uint64_t sequence, std::int64_t timestamp_ns);
/// Whether a sample can be written into a world: finite, and a quaternion that
/// normalises (norm within [0.5, 2]).
[[nodiscard]] bool sim_world_sample_valid(const mhd_dds_SimWorld& sample);

class SimWorldPublisher {
 public:
  /// Publishes in rig `rig_id`'s partition. `participant` must outlive this. Throws
  /// DdsError (NOT_ALLOWED_BY_SECURITY when the identity may not publish mhd_sim_world).
  SimWorldPublisher(const Participant& participant, std::uint32_t rig_id);
  /// Never blocks (best-effort).
  void publish(const simulation::SimulatedWorld& world, std::int64_t timestamp_ns);
  [[nodiscard]] std::uint64_t published() const { return sequence_; }

 private:
  std::uint32_t rig_id_;
  Publisher<mhd_dds_SimWorld> publisher_;
  std::uint64_t sequence_ = 0;
};

class SimWorldSubscriber {
 public:
  /// Reads rig `rig_id`'s partition. `participant` must outlive this.
  SimWorldSubscriber(const Participant& participant, std::uint32_t rig_id);
  /// Takes what arrived and writes the newest valid sample of this rig into `world`;
  /// true when it wrote one. Never blocks.
  bool apply_newest(simulation::SimulatedWorld& world);
  /// Blocks until a sample arrives or timeout_ns passes.
  bool wait(dds_duration_t timeout_ns) { return subscriber_.reader().wait(timeout_ns); }
  [[nodiscard]] std::uint64_t applied() const { return applied_; }
  /// Samples of another rig, not finite, or with a quaternion that does not normalise.
  [[nodiscard]] std::uint64_t rejected() const { return rejected_; }

 private:
  std::uint32_t rig_id_;
  Subscriber<mhd_dds_SimWorld> subscriber_;
  mhd_dds_SimWorld newest_{};  ///< of the current take
  std::uint64_t applied_ = 0;
  std::uint64_t rejected_ = 0;
};

}  // namespace mhd::dds
