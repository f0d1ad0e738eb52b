#pragma once
// Moving objects and the proxy (docs/proxy.md "Moving objects"). Between two ticks the
// objects move; before the proxy steps towards the new HIP, each moved object acts on it:
// a proxy resting on the object rides with it, and a free proxy that the object's surface
// reaches is pushed along, found by sweeping the proxy's motion relative to the object
// (in the object's frame, the proxy moves and the object stands still). Either way the
// proxy's move through the world is swept against the other objects, so it never tunnels
// into a resting surface either; squeezed between the two, it stays outside the resting
// one and the squeeze is reported.

#include "proxy/god_object.h"

#include <span>

namespace mhd {

struct CarryOutput {
  int rode = 0;      ///< moved objects the proxy rested on and moved with
  int pushed = 0;    ///< moved objects whose surface reached the free proxy and pushed it
  bool squeezed = false;  ///< a carried proxy met another surface and stopped there
};

/// The world's objects were at X_WO_before[i] at the last tick and are at world.pose(i)
/// now. Moves state.proxy_W as those motions carry it (see above) and turns the
/// constraint planes of each moved object with it. Objects whose pose did not change
/// cost nothing. Precondition: X_WO_before has one pose per object. Allocates nothing.
CarryOutput carry_proxy(const CollisionWorld& world, std::span<const Pose> X_WO_before, double skin_m,
                        ProxyState& state);

}  // namespace mhd
