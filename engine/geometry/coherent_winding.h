#pragma once
// Turns triangles wound against their neighbours to the winding of the surface they lie
// in. Files from some tools mix windings; a mixed surface touched from one side only
// (touchable="front") has a hole at every triangle wound the other way, and its vertex
// normals cancel there.

#include "geometry/triangle_mesh.h"

#include <cstddef>

namespace mhd {

/// Makes every surface of `mesh` wound one way. A surface is the triangles reachable
/// from one another across edges that exactly two triangles share (an edge of three or
/// more is a seam between surfaces, and so is a corner shared by nothing else). Two
/// neighbours agree when they walk their shared edge in opposite directions. In each
/// surface the winding of the greater part of its area is kept, so a surface wound one
/// way throughout, inside-out or not, stays as it is; the rest is turned to it. A surface
/// with no consistent winding (a Moebius strip) keeps the one met first. Vertex normals
/// are not recomputed. Returns how many triangles were turned.
/// A mesh with no edge walked the same way twice is wound one way already and costs one
/// pass over its edges (12 bytes a triangle and 8 a vertex); otherwise the surfaces are
/// walked (17 and 8 more). A vertex of any number of triangles costs no more than a sort.
std::size_t orient_coherently(TriangleMesh& mesh);

}  // namespace mhd
