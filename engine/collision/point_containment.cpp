#include "collision/point_containment.h"

#include "collision/exact_sweep.h"

#include <array>
#include <cmath>
#include <optional>
#include <span>

namespace mhd {

bool point_inside_surface(const CollisionWorld& world, const Eigen::Vector3d& p_W) {
  if (!p_W.allFinite()) return false;
  // Skewed directions, so a ray rarely runs along an edge or a face of a modelled shape.
  static const std::array<Eigen::Vector3d, 6> kDirections{
      Eigen::Vector3d(0.1234, 1.0, 0.0567).normalized(),  Eigen::Vector3d(-0.0711, -1.0, 0.1033).normalized(),
      Eigen::Vector3d(1.0, 0.0913, -0.1471).normalized(), Eigen::Vector3d(-1.0, 0.1627, 0.0389).normalized(),
      Eigen::Vector3d(0.0841, -0.1317, 1.0).normalized(), Eigen::Vector3d(0.1553, 0.0473, -1.0).normalized()};
  constexpr double kRayLength_m = 1000.0;
  constexpr double kSkin_m = 1e-9;
  // The first hit decides only when it is clean: a ray grazing the face it meets, or
  // meeting it next to an edge, may have slipped past the neighbour that really is
  // first (found by the pop-through stress: a point 1 um outside the dolphin was called
  // inside). Then the next direction is asked; with none clean, the answer is "inside",
  // the side on which the proxy waits instead of starting inside an object.
  constexpr double kMinCosine = 0.05;
  constexpr double kEdgeClearance_m = 1e-7;
  // Exact primitives are solids with a signed distance; the rays below pass them.
  constexpr std::size_t kMaxExactPassed = 16;
  // Faces met within this of one another along a ray are met at once: the two windings
  // of a two-sided face, or the shared square of two solids that touch. Each counts +1
  // where the ray leaves through it and -1 where it enters, and their sum decides, so
  // such a pair, summing to 0, is passed like an exact shape: a sheet wound both ways
  // encloses nothing, and two touching solids are one.
  constexpr double kCoincident_m = 1e-8;
  // Shapes and faces one ray may pass; past them it is not trusted (as below).
  constexpr std::size_t kMaxPassed = 64;
  for (int i = 0; i < world.object_count(); ++i) {
    const ExactShape* shape = world.exact_shape(i);
    if (shape != nullptr && exact_signed_distance(*shape, world.pose(i).inverse(Eigen::Isometry) * p_W) < 0.0) {
      return true;
    }
  }
  // +1 or -1 for a clean hit of a triangle (see above), 0 for one not to be trusted.
  const auto leaves_through = [&](const SweepHit& hit, const Eigen::Vector3d& d) {
    const Eigen::Vector3d n = world.face_normal_W(hit.where);
    const double cosine = n.dot(d);
    if (std::abs(cosine) < kMinCosine) return 0;
    const auto v = world.triangle_W(hit.where);
    const Eigen::Vector3d x = p_W + (n.dot(v[0] - p_W) / cosine) * d;  // where the ray meets the plane
    if (!world.projects_onto_triangle(hit.where, x, -kEdgeClearance_m)) return 0;
    return cosine > 0.0 ? 1 : -1;
  };
  for (const Eigen::Vector3d& d : kDirections) {
    std::array<TriangleRef, kMaxPassed> passed{};
    std::size_t n_passed = 0;
    std::size_t n_exact = 0;
    const auto sweep_past = [&](const Eigen::Vector3d& to) {
      return world.sweep(p_W, to, kSkin_m, std::span<const TriangleRef>(passed.data(), n_passed));
    };
    const Eigen::Vector3d far = p_W + kRayLength_m * d;
    std::optional<bool> inside;  // what this direction decides
    bool trusted = true;
    while (trusted && !inside) {
      auto hit = sweep_past(far);
      if (hit && hit->where.triangle == kExactSurface) {
        if (n_exact == kMaxExactPassed || n_passed == kMaxPassed) return true;  // the conservative side, as below
        ++n_exact;
        passed[n_passed++] = hit->where;
        continue;
      }
      if (!hit) return false;
      // The first face met and every face met where it is.
      const Eigen::Vector3d reach = p_W + (hit->t_stop * kRayLength_m + kCoincident_m) * d;
      int sum = 0;
      while (hit) {
        const int through = leaves_through(*hit, d);
        if (through == 0 || n_passed == kMaxPassed) {
          trusted = false;
          break;
        }
        sum += through;
        passed[n_passed++] = hit->where;
        hit = sweep_past(reach);
      }
      if (trusted && sum != 0) inside = sum > 0;
    }
    if (inside) return *inside;
  }
  return true;
}

}  // namespace mhd
