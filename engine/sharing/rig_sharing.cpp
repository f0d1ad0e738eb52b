#include "sharing/rig_sharing.h"

#include "proxy/contact_reaction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mhd {

RigSharing::RigSharing(std::uint32_t rig_id, std::span<const SharedObjectDeclaration> objects,
                       const CollisionWorld& world, const RigSharingSettings& settings)
    : rig_id_(rig_id), pushes_(settings.pushes) {
  if (objects.size() > static_cast<std::size_t>(kMaxObjects)) {
    throw std::invalid_argument("more than " + std::to_string(kMaxObjects) + " shared objects");
  }
  replicas_.reserve(objects.size());
  for (const SharedObjectDeclaration& d : objects) {
    if (d.object < 0 || d.object >= world.object_count()) {
      throw std::invalid_argument("shared object " + std::to_string(d.id) + " is not in the world");
    }
    if (slot_of_id(d.id) >= 0 || slot_of_object(d.object) >= 0) {
      throw std::invalid_argument("shared object " + std::to_string(d.id) + " is declared twice");
    }
    const auto rigs = std::span<const std::uint32_t>(d.rigs.data(), static_cast<std::size_t>(std::max(d.rig_count, 0)));
    if (std::find(rigs.begin(), rigs.end(), rig_id) == rigs.end()) {
      throw std::invalid_argument("rig " + std::to_string(rig_id) + " does not share object " + std::to_string(d.id));
    }
    if (!authority_.share(count_, d.rigs.data(), d.rig_count)) {
      throw std::invalid_argument("shared object " + std::to_string(d.id) + " has no rigs, too many, or one twice");
    }
    objects_[static_cast<std::size_t>(count_)] = d;
    replicas_.emplace_back(world.pose(d.object), settings.replica);
    fades_[static_cast<std::size_t>(count_)] = ReplicaFade(settings.fade);
    ++count_;
  }
}

std::vector<char> RigSharing::replicas(std::size_t object_count) const {
  std::vector<char> out(object_count, 0);
  for (int s = 0; s < count_; ++s) {
    const auto object = static_cast<std::size_t>(objects_[static_cast<std::size_t>(s)].object);
    if (object < object_count) out[object] = authority_.authority(s) != rig_id_ ? 1 : 0;
  }
  return out;
}

bool RigSharing::holds(int object) const noexcept {
  const int s = slot_of_object(object);
  return s >= 0 && authority_.authority(s) == rig_id_;
}

int RigSharing::slot_of_id(std::uint32_t id) const noexcept {
  for (int s = 0; s < count_; ++s) {
    if (objects_[static_cast<std::size_t>(s)].id == id) return s;
  }
  return -1;
}

int RigSharing::slot_of_object(int object) const noexcept {
  for (int s = 0; s < count_; ++s) {
    if (objects_[static_cast<std::size_t>(s)].object == object) return s;
  }
  return -1;
}

void RigSharing::receive_state(std::uint32_t object_id, SharedObjectState state, double now_s) noexcept {
  const int s = slot_of_id(object_id);
  if (s < 0) {
    ++counters_.unknown_object;
    return;
  }
  state.object = s;
  // A rig runs the body of an object it holds, for the whole run: no state moves it,
  // not even a later term's (a hand-over away from a running rig is not supported).
  if (authority_.authority(s) == rig_id_ || authority_.judge(state) != StateVerdict::Obeyed) {
    ++counters_.states_ignored;
    return;
  }
  replicas_[static_cast<std::size_t>(s)].accept(state, now_s);
  ++counters_.states_obeyed;
}

void RigSharing::receive_push(std::uint32_t object_id, SharedPush push) noexcept {
  const int s = slot_of_id(object_id);
  if (s < 0) {
    ++counters_.unknown_object;
    return;
  }
  // Only the authority runs the object's physics: a push for an object held elsewhere
  // (sent before a hand-over was heard) has nothing to act on here.
  push.object = objects_[static_cast<std::size_t>(s)].object;
  if (authority_.authority(s) != rig_id_ || push.from_rig == rig_id_ || !pushes_.receive(push)) {
    ++counters_.pushes_ignored;
    return;
  }
  ++counters_.pushes_kept;
}

void RigSharing::before_move(double t_s, MovingWorld& moving) noexcept {
  for (int s = 0; s < count_; ++s) {
    if (authority_.authority(s) == rig_id_) continue;
    const ObjectReplica& r = replicas_[static_cast<std::size_t>(s)];
    moving.drive(objects_[static_cast<std::size_t>(s)].object, r.X_WO_at(t_s), r.twist_at(t_s));
  }
}

double RigSharing::state_age_s(int slot, double t_s) const noexcept {
  if (authority_.authority(slot) == rig_id_) return 0.0;
  const ObjectReplica& r = replicas_[static_cast<std::size_t>(slot)];
  // Before the first state the replica is the scene's pose at 0, as old as the run.
  return r.has_state() ? r.age_s(t_s) : std::numeric_limits<double>::infinity();
}

double RigSharing::force_gain(double t_s, double dt_s, const ProxyState& proxy,
                              const Eigen::Vector3d& force_W_N) noexcept {
  std::array<double, kMaxObjects> gain{};
  for (int s = 0; s < count_; ++s) {
    const bool replica = authority_.authority(s) != rig_id_;
    gain[static_cast<std::size_t>(s)] =
        replica ? fades_[static_cast<std::size_t>(s)].update(state_age_s(s, t_s), dt_s) : 1.0;
  }
  double least = 1.0;
  const ContactReactions reactions = contact_reactions(proxy, force_W_N);
  for (int i = 0; i < reactions.count; ++i) {
    const int s = slot_of_object(reactions.on[static_cast<std::size_t>(i)].object);
    if (s >= 0) least = std::min(least, gain[static_cast<std::size_t>(s)]);
  }
  return least;
}

void RigSharing::after_render(double t_s, const ProxyState& proxy, const Eigen::Vector3d& force_W_N,
                              MovingWorld& moving) noexcept {
  outbox_count_ = 0;
  // The other rigs' pushes act on the bodies held here until the next reaction.
  pushes_.for_each_acting(t_s, [&](const SharedPush& p) {
    if (!holds(p.object)) return;
    moving.add_push(p.object, p.f_W_N, moving.world().pose(p.object) * p.p_O_m);
  });
  std::array<Eigen::Vector3d, kMaxObjects> f_W_N;
  f_W_N.fill(Eigen::Vector3d::Zero());
  const ContactReactions reactions = contact_reactions(proxy, force_W_N);
  for (int i = 0; i < reactions.count; ++i) {
    const ContactReaction& on = reactions.on[static_cast<std::size_t>(i)];
    const int s = slot_of_object(on.object);
    if (s >= 0) f_W_N[static_cast<std::size_t>(s)] += on.f_W_N;
  }
  for (int s = 0; s < count_; ++s) {
    if (authority_.authority(s) == rig_id_) {
      send_state(s, t_s, moving);
    } else {
      send_push(s, t_s, f_W_N[static_cast<std::size_t>(s)], proxy.proxy_W, moving);
    }
  }
}

void RigSharing::send_state(int s, double t_s, const MovingWorld& moving) noexcept {
  const int object = objects_[static_cast<std::size_t>(s)].object;
  SharingMessage& m = outbox_[static_cast<std::size_t>(outbox_count_++)];
  m.kind = SharingMessage::Kind::State;
  m.object_id = objects_[static_cast<std::size_t>(s)].id;
  const std::span<const ObjectTwist> twists = moving.twists();
  m.state = SharedObjectState{object,
                              rig_id_,
                              authority_.epoch(s),
                              ++state_sequence_,
                              t_s,
                              moving.world().pose(object),
                              static_cast<std::size_t>(object) < twists.size() ? twists[static_cast<std::size_t>(object)]
                                                                              : ObjectTwist{}};
  ++counters_.states_sent;
}

void RigSharing::send_push(int s, double t_s, const Eigen::Vector3d& f_W_N, const Eigen::Vector3d& p_W_m,
                           const MovingWorld& moving) noexcept {
  const bool pushing = f_W_N.squaredNorm() > 0.0 && p_W_m.allFinite();
  bool& was_pushing = pushing_[static_cast<std::size_t>(s)];
  if (!pushing && !was_pushing) return;  // nothing to say: the last push said zero
  was_pushing = pushing;
  const int object = objects_[static_cast<std::size_t>(s)].object;
  SharingMessage& m = outbox_[static_cast<std::size_t>(outbox_count_++)];
  m.kind = SharingMessage::Kind::Push;
  m.object_id = objects_[static_cast<std::size_t>(s)].id;
  // The point in the object's own frame: the object moves between here and the
  // authority, the material point pushed does not.
  const Eigen::Vector3d p_O_m =
      pushing ? Eigen::Vector3d(moving.world().pose(object).inverse() * p_W_m) : Eigen::Vector3d::Zero();
  m.push = SharedPush{object, rig_id_, ++push_sequence_, t_s, pushing ? f_W_N : Eigen::Vector3d::Zero(), p_O_m};
  ++counters_.pushes_sent;
}

}  // namespace mhd
