#pragma once
// A scene ready to touch: collision geometry with BVHs, one material per object, the
// objects' scripted motions and the proxy settings. Immutable once compiled (moving
// objects move in a copy of the world, never the BVHs).

#include "collision/collision_world.h"
#include "geometry/object_dynamics.h"
#include "geometry/object_motion.h"
#include "material/haptic_material.h"
#include "proxy/god_object.h"
#include "sharing/rig_sharing.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mhd {

/// The objects a scene shares with other rigs (<sharing>): this rig's id, and each
/// object with its index in the world.
struct CompiledSharing {
  std::uint32_t rig_id = 0;
  std::vector<SharedObjectDeclaration> objects;
};

struct CompiledScene {
  std::string name;
  CollisionWorld world;
  std::vector<HapticMaterial> materials;  ///< indexed like world objects
  std::vector<std::string> object_names;  ///< indexed like world objects
  /// Scripted motions, indexed like world objects (none: the object stays). The world
  /// holds every object at its pose at t = 0; MovingWorld moves a copy.
  std::vector<std::optional<ObjectMotion>> motions;
  /// Pushable objects' mass and friction, indexed like world objects (none: not pushable).
  /// MovingWorld simulates them (RigidBodyWorld).
  std::vector<std::optional<ObjectDynamics>> dynamics;
  ProxySettings proxy;
  std::size_t triangle_count = 0;
  std::optional<CompiledSharing> sharing;  ///< none: the scene shares nothing
};

}  // namespace mhd
