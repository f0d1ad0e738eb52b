#pragma once
// Tessellated primitives. MHD renders every shape through the same proxy and BVH
// code path, so primitives become meshes (closed, outward-facing, CCW from outside).

#include "geometry/triangle_mesh.h"

namespace mhd {

/// Square plane in z = 0 facing +z, centred on the origin, side lengths in metres.
/// Two-sided: the proxy stays on whichever side it approaches from.
[[nodiscard]] TriangleMesh make_plane_mesh(double size_x_m, double size_y_m);

/// Axis-aligned box centred on the origin.
[[nodiscard]] TriangleMesh make_box_mesh(const Eigen::Vector3d& size_m);

/// Icosphere centred on the origin; subdivisions 0..7 (20 * 4^n triangles).
[[nodiscard]] TriangleMesh make_sphere_mesh(double radius_m, int subdivisions);

/// UV sphere with `rings` latitude bands and `segments` longitude bands
/// (2 * segments * (rings - 1) triangles); used for large benchmark spheres.
[[nodiscard]] TriangleMesh make_uv_sphere_mesh(double radius_m, int rings, int segments);

/// Capsule along z, centred on the origin: a cylinder of `length_m` between the centres of
/// two hemispherical caps of `radius_m`, tessellated as a UV sphere of 2 * rings + 1
/// latitude bands split at its equator (every vertex on the true surface).
[[nodiscard]] TriangleMesh make_capsule_mesh(double radius_m, double length_m, int rings, int segments);
/// The latitude bands per cap that a capsule of `segments` round its axis is drawn with.
[[nodiscard]] constexpr int capsule_rings(int segments) { return segments / 4 > 1 ? segments / 4 : 1; }
/// Capped cylinder along z, centred on the origin.
[[nodiscard]] TriangleMesh make_cylinder_mesh(double radius_m, double height_m, int segments);

}  // namespace mhd
