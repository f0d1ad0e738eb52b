#include "proxy/moving_world.h"

#include "proxy/contact_reaction.h"

#include <stdexcept>
#include <string>

namespace mhd {

MovingWorld::MovingWorld(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions)
    : world_(world), motions_(std::move(motions)) {
  if (motions_.size() != static_cast<std::size_t>(world_.object_count())) {
    throw std::invalid_argument("MovingWorld: one motion entry per object is needed");
  }
  X_WO_before_.resize(motions_.size());
  twists_.resize(motions_.size());
  driven_.assign(motions_.size(), 0);
  X_WO_driven_.resize(motions_.size());
  twists_driven_.resize(motions_.size());
  for (const auto& m : motions_) moving_count_ += m.has_value() ? 1 : 0;
}

MovingWorld::MovingWorld(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions,
                         std::span<const std::optional<ObjectDynamics>> dynamics, const RigidBodySettings& physics)
    : MovingWorld(world, std::move(motions), dynamics, std::span<const bool>(), physics) {}

MovingWorld::MovingWorld(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions,
                         std::span<const std::optional<ObjectDynamics>> dynamics, std::span<const bool> driven,
                         const RigidBodySettings& physics)
    : MovingWorld(world, std::move(motions)) {
  if (!driven.empty()) {
    if (driven.size() != motions_.size()) {
      throw std::invalid_argument("MovingWorld: one driven entry per object is needed");
    }
    for (std::size_t i = 0; i < driven.size(); ++i) {
      if (!driven[i]) continue;
      if (motions_[i] || (i < dynamics.size() && dynamics[i])) {
        throw std::invalid_argument("MovingWorld: driven object " + std::to_string(i) +
                                    " also has a motion or dynamics");
      }
      driven_[i] = 1;
      X_WO_driven_[i] = world_.pose(static_cast<int>(i));
      ++moving_count_;
    }
  }
  bool any_body = false;
  for (const auto& d : dynamics) any_body = any_body || d.has_value();
  if (!any_body) return;
  if (dynamics.size() != motions_.size()) {
    throw std::invalid_argument("MovingWorld: one dynamics entry per object is needed");
  }
  // Still objects are the bodies' static colliders; scripted ones are left out.
  const auto still = std::make_unique<bool[]>(motions_.size());
  for (std::size_t i = 0; i < motions_.size(); ++i) {
    if (motions_[i] && dynamics[i]) {
      throw std::invalid_argument("MovingWorld: object " + std::to_string(i) + " has both a motion and dynamics");
    }
    still[i] = !motions_[i] && !dynamics[i] && driven_[i] == 0;
  }
  physics_ = std::make_unique<RigidBodyWorld>(world_, dynamics, std::span<const bool>(still.get(), motions_.size()),
                                              physics);
}

void MovingWorld::place(double t_s) noexcept {
  for (std::size_t i = 0; i < motions_.size(); ++i) {
    if (driven_[i] != 0) {
      world_.set_pose(static_cast<int>(i), X_WO_driven_[i]);
      twists_[i] = twists_driven_[i];
      continue;
    }
    if (!motions_[i]) continue;
    world_.set_pose(static_cast<int>(i), motions_[i]->X_WO_at(t_s));
    twists_[i] = ObjectTwist{motions_[i]->v_W_origin_at(t_s), motions_[i]->omega_W_at(t_s)};
  }
}

CarryOutput MovingWorld::advance(double t_s, ProxyState& proxy, double skin_m) noexcept {
  if (!moves()) return {};
  for (std::size_t i = 0; i < motions_.size(); ++i) X_WO_before_[i] = world_.pose(static_cast<int>(i));
  place(t_s);
  if (physics_) {
    (void)physics_->advance(t_s);
    for (std::size_t i = 0; i < motions_.size(); ++i) {
      const int object = static_cast<int>(i);
      if (!physics_->is_body(object)) continue;
      world_.set_pose(object, physics_->X_WO(object));
      twists_[i] = ObjectTwist{physics_->v_W_origin_mps(object), physics_->omega_W_radps(object)};
    }
  }
  return carry_proxy(world_, X_WO_before_, skin_m, proxy);
}

void MovingWorld::set_body_velocity(int object, const ObjectTwist& twist_W) noexcept {
  if (physics_) physics_->set_velocity(object, twist_W.v_W_origin_mps, twist_W.omega_W_radps);
}

void MovingWorld::drive(int object, const Pose& X_WO, const ObjectTwist& twist_W) noexcept {
  if (object < 0 || static_cast<std::size_t>(object) >= driven_.size() || driven_[static_cast<std::size_t>(object)] == 0) {
    return;
  }
  X_WO_driven_[static_cast<std::size_t>(object)] = X_WO;
  twists_driven_[static_cast<std::size_t>(object)] = twist_W;
}

void MovingWorld::add_push(int object, const Eigen::Vector3d& f_W_N, const Eigen::Vector3d& p_W_m) noexcept {
  if (physics_) physics_->add_force(object, f_W_N, p_W_m);
}

void MovingWorld::apply_reaction(const ProxyState& proxy, const Eigen::Vector3d& force_W_N) noexcept {
  if (!physics_) return;
  physics_->clear_forces();
  const ContactReactions r = contact_reactions(proxy, force_W_N);
  for (int i = 0; i < r.count; ++i) {
    const ContactReaction& on = r.on[static_cast<std::size_t>(i)];
    physics_->apply_force(on.object, on.f_W_N, proxy.proxy_W);
  }
}

}  // namespace mhd
