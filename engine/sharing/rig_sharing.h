#pragma once
// One rig's part in the objects it shares with other rigs (docs/shared-objects.md), as
// its haptic tick runs it. For each shared object either this rig is the authority (the
// object's body is simulated here, pushed by this rig's user and by the pushes the other
// rigs send), or it renders a replica of the authority's states (a driven object of the
// rig's MovingWorld) and sends the authority its user's push. The tick calls:
//   receive_state / receive_push   what the link brought since the last tick
//   before_move(t, moving)         replicas posed where their states say at t
//   force_gain(t, dt, proxy)       the force from a stale replica fades (ReplicaFade)
//   after_render(t, proxy, f, ...) remote pushes held for the next step; this tick's
//                                  states and pushes into the outbox
// Objects are named three ways: the scene's object index, the id on the link (the same
// in every rig's scene), and a slot here (0 .. count-1). Fixed size after construction,
// no allocation per tick: runs on the haptic thread.

#include "proxy/god_object.h"
#include "proxy/moving_world.h"
#include "sharing/object_authority.h"
#include "sharing/object_replica.h"
#include "sharing/remote_pushes.h"
#include "sharing/replica_fade.h"
#include "sharing/shared_object_state.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace mhd {

/// One object the scene shares: its index in the scene, its id on the link, and the rigs
/// that may hold its authority (rigs[0] holds it first).
struct SharedObjectDeclaration {
  int object = -1;
  std::uint32_t id = 0;
  std::array<std::uint32_t, kMaxAuthorityRigs> rigs{};
  int rig_count = 0;
};

struct RigSharingSettings {
  ReplicaSettings replica;
  RemotePushSettings pushes;
  ReplicaFadeSettings fade;
};

/// What a tick sends: the authority's state of an object, or this rig's push on one.
struct SharingMessage {
  enum class Kind : std::uint8_t { State, Push };
  Kind kind = Kind::State;
  std::uint32_t object_id = 0;
  SharedObjectState state;  ///< Kind::State (its `object` is the scene's index)
  SharedPush push;          ///< Kind::Push (its `object` is the scene's index)
};

struct SharingCounters {
  std::uint64_t states_sent = 0, pushes_sent = 0;
  std::uint64_t states_obeyed = 0, states_ignored = 0;  ///< ignored: ObjectAuthority's verdicts
  std::uint64_t pushes_kept = 0, pushes_ignored = 0;    ///< ignored: old, not finite, or not for an object held here
  std::uint64_t unknown_object = 0;                     ///< a message for an id this scene does not share
};

class RigSharing {
 public:
  /// At most kMaxSharedObjects objects, each with its rigs; this rig on every list.
  static constexpr int kMaxObjects = kMaxSharedObjects;

  /// `world` holds every object at its pose at t = 0 (the replicas' start). Throws
  /// std::invalid_argument for a declaration the scene check refuses (an object out of
  /// the world, an id twice, this rig not on an object's list, too many objects or rigs).
  RigSharing(std::uint32_t rig_id, std::span<const SharedObjectDeclaration> objects, const CollisionWorld& world,
             const RigSharingSettings& settings = {});

  /// [i]: object i is a replica here (its authority is another rig), for MovingWorld.
  [[nodiscard]] std::vector<char> replicas(std::size_t object_count) const;
  [[nodiscard]] bool holds(int object) const noexcept;

  /// A state from the link, for the object with `object_id`, arrived at now_s.
  void receive_state(std::uint32_t object_id, SharedObjectState state, double now_s) noexcept;
  /// A push from the link, for the object with `object_id`.
  void receive_push(std::uint32_t object_id, SharedPush push) noexcept;

  /// Poses every replica where its state says at t_s.
  void before_move(double t_s, MovingWorld& moving) noexcept;
  /// The gain for the force of a proxy touching objects (contact_reactions of proxy and
  /// force_W_N): the least fade of the replicas it touches, 1 when it touches none. Steps
  /// every replica's fade by dt_s.
  double force_gain(double t_s, double dt_s, const ProxyState& proxy, const Eigen::Vector3d& force_W_N) noexcept;
  /// After the tick's reaction went to the bodies (MovingWorld::apply_reaction): holds
  /// the other rigs' acting pushes for the next step, and fills the outbox with this
  /// tick's messages (a state per object held here; this rig's push on each replica it
  /// touches, and one zero push when it lets go).
  void after_render(double t_s, const ProxyState& proxy, const Eigen::Vector3d& force_W_N, MovingWorld& moving) noexcept;

  [[nodiscard]] std::span<const SharingMessage> outbox() const noexcept {
    return std::span<const SharingMessage>(outbox_.data(), static_cast<std::size_t>(outbox_count_));
  }
  [[nodiscard]] const SharingCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] int object_count() const noexcept { return count_; }
  [[nodiscard]] const SharedObjectDeclaration& declaration(int slot) const noexcept {
    return objects_[static_cast<std::size_t>(slot)];
  }
  [[nodiscard]] std::uint32_t authority(int slot) const noexcept { return authority_.authority(slot); }
  /// The age at t_s of the state a replica renders (0 for an object held here).
  [[nodiscard]] double state_age_s(int slot, double t_s) const noexcept;

 private:
  [[nodiscard]] int slot_of_id(std::uint32_t id) const noexcept;
  [[nodiscard]] int slot_of_object(int object) const noexcept;
  void send_state(int slot, double t_s, const MovingWorld& moving) noexcept;
  void send_push(int slot, double t_s, const Eigen::Vector3d& f_W_N, const Eigen::Vector3d& p_W_m,
                 const MovingWorld& moving) noexcept;

  std::uint32_t rig_id_;
  int count_ = 0;
  std::array<SharedObjectDeclaration, kMaxObjects> objects_{};
  ObjectAuthority authority_;
  std::vector<ObjectReplica> replicas_;  // [slot]; used for the objects held elsewhere
  std::array<ReplicaFade, kMaxObjects> fades_;
  std::array<bool, kMaxObjects> pushing_{};  // [slot]: the last push sent was not zero
  RemotePushes pushes_;
  std::uint64_t state_sequence_ = 0, push_sequence_ = 0;
  std::array<SharingMessage, 2 * kMaxObjects> outbox_{};
  int outbox_count_ = 0;
  SharingCounters counters_;
};

}  // namespace mhd
