#pragma once
// A scene ready to touch: collision geometry with BVHs, one material per object and
// the proxy settings. Immutable once compiled (object poses change through the
// CollisionWorld, never the BVHs).

#include "collision/collision_world.h"
#include "material/haptic_material.h"
#include "proxy/god_object.h"

#include <string>
#include <vector>

namespace mhd {

struct CompiledScene {
  std::string name;
  CollisionWorld world;
  std::vector<HapticMaterial> materials;  ///< indexed like world objects
  std::vector<std::string> object_names;  ///< indexed like world objects
  ProxySettings proxy;
  std::size_t triangle_count = 0;
};

}  // namespace mhd
