#include "proxy/moving_world.h"

#include <stdexcept>

namespace mhd {

MovingWorld::MovingWorld(const CollisionWorld& world, std::vector<std::optional<ObjectMotion>> motions)
    : world_(world), motions_(std::move(motions)) {
  if (motions_.size() != static_cast<std::size_t>(world_.object_count())) {
    throw std::invalid_argument("MovingWorld: one motion entry per object is needed");
  }
  X_WO_before_.resize(motions_.size());
  twists_.resize(motions_.size());
  for (const auto& m : motions_) moving_count_ += m.has_value() ? 1 : 0;
}

void MovingWorld::place(double t_s) noexcept {
  for (std::size_t i = 0; i < motions_.size(); ++i) {
    if (!motions_[i]) continue;
    world_.set_pose(static_cast<int>(i), motions_[i]->X_WO_at(t_s));
    twists_[i] = ObjectTwist{motions_[i]->v_W_origin_at(t_s), motions_[i]->omega_W_at(t_s)};
  }
}

CarryOutput MovingWorld::advance(double t_s, ProxyState& proxy, double skin_m) noexcept {
  if (!moves()) return {};
  for (std::size_t i = 0; i < motions_.size(); ++i) X_WO_before_[i] = world_.pose(static_cast<int>(i));
  place(t_s);
  return carry_proxy(world_, X_WO_before_, skin_m, proxy);
}

}  // namespace mhd
