#include "scene_compiler/exact_primitive.h"

#include <type_traits>

namespace mhd {

std::optional<ExactShape> exact_shape_of(const ShapeSource& source) {
  return std::visit(
      [](const auto& s) -> std::optional<ExactShape> {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, MeshSource>) {
          return std::nullopt;
        } else {
          if (!s.exact) return std::nullopt;
          ExactShape e;
          if constexpr (std::is_same_v<S, PlaneSource>) {
            e.kind = ExactKind::HalfSpace;
          } else if constexpr (std::is_same_v<S, SphereSource>) {
            e.kind = ExactKind::Sphere;
            e.radius_m = s.radius_m;
          } else if constexpr (std::is_same_v<S, BoxSource>) {
            e.kind = ExactKind::Box;
            e.half_extents_m = 0.5 * s.size_m;
          } else if constexpr (std::is_same_v<S, CylinderSource>) {
            e.kind = ExactKind::Cylinder;
            e.radius_m = s.radius_m;
            e.half_height_m = 0.5 * s.height_m;
          } else {
            static_assert(std::is_same_v<S, CapsuleSource>);
            e.kind = ExactKind::Capsule;
            e.radius_m = s.radius_m;
            e.half_height_m = 0.5 * s.length_m;
          }
          return e;
        }
      },
      source);
}

}  // namespace mhd
