#pragma once
// Internal to mhd_viewer (includes OSG): the scene's objects as an OSG graph, and the
// floor grid. Meshes load through engine/mesh_io, primitives tessellate through
// engine/geometry, exactly as the haptic side sees them.

#include "diagnostics/result.h"
#include "geometry/triangle_mesh.h"
#include "scene/scene_description.h"

#include <Eigen/Geometry>
#include <osg/Geometry>
#include <osg/Group>
#include <osg/MatrixTransform>
#include <osg/ref_ptr>

#include <string>
#include <vector>

namespace mhd::viewer {

struct SceneGraph {
  osg::ref_ptr<osg::Group> root;
  /// Bounds of the non-plane objects in the world (empty when there are none).
  Eigen::AlignedBox3d objects_bounds_W;
  /// Each object's transform, indexed like SceneDescription::objects (null where the
  /// object could not be drawn): a moving object is moved by setting its matrix.
  std::vector<osg::ref_ptr<osg::MatrixTransform>> object_transforms;
};

/// The scene's objects as OSG nodes, or one error per object that cannot be drawn
/// ("object 'x': mesh file '...': file not found").
[[nodiscard]] Result<SceneGraph, std::vector<std::string>> build_scene_graph(const SceneDescription& scene);

/// A triangle mesh as OSG geometry in one colour; empty reason on success, else why OSG
/// cannot draw it ("it has no triangles", "vertex 12 is not finite", ...).
[[nodiscard]] osg::ref_ptr<osg::Geometry> mesh_geometry(const TriangleMesh& mesh, const Eigen::Vector4f& rgba,
                                                        std::string& reason);

/// Lines on the floor (y = 0) every `minor_m`, brighter every `major_m`, over +-half_size_m.
[[nodiscard]] osg::ref_ptr<osg::Node> floor_grid(double half_size_m, double major_m, double minor_m);

}  // namespace mhd::viewer
