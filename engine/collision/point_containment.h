#pragma once
// Whether a point lies inside a closed surface of the world, for starting the proxy: a
// proxy placed inside an object would render that object inside out (pull the hand in).
// The test casts a ray (skewed, so it does not run along edges of axis-aligned meshes)
// and looks at the first surface it meets: leaving through a face whose outward normal
// (counter-clockwise winding) points along the ray means the point is inside. Faces met
// at the same place count together, +1 for each the ray leaves through and -1 for each
// it enters, and a sum of 0 is passed: a face wound both ways (a two-sided sheet)
// encloses nothing, and two closed solids that share a face are one. A hit at a grazing
// angle or next to an edge is not trusted: the next of six directions is asked, and with
// none clean the answer is "inside" (the proxy waits rather than start inside). Needs
// outward-wound meshes, as the scene format requires; an open surface counts as a
// half-space (below the floor is inside the floor).

#include "collision/collision_world.h"

#include <Eigen/Core>

namespace mhd {

[[nodiscard]] bool point_inside_surface(const CollisionWorld& world, const Eigen::Vector3d& p_W);

}  // namespace mhd
