#include "viewer/scene_graph.h"

#include "geometry/primitive_mesh.h"
#include "mesh_io/mesh_loader.h"
#include "viewer/osg_convert.h"
#include "viewer/scene_colours.h"

#include <fmt/core.h>
#include <osg/BlendFunc>
#include <osg/LightModel>
#include <osg/LineWidth>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osg/PolygonOffset>

#include <cmath>
#include <limits>
#include <type_traits>
#include <variant>

namespace mhd::viewer {
namespace {

/// The object's shape as a mesh in its own frame, or an error message.
std::optional<TriangleMesh> shape_mesh(const ShapeSource& shape, std::string& error) {
  return std::visit(
      [&](const auto& s) -> std::optional<TriangleMesh> {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, MeshSource>) {
          Result<LoadedMesh, MeshLoadError> loaded = load_mesh_file(s.file, s.scale_to_m);
          if (!loaded.ok()) {
            error = loaded.error().message();
            return std::nullopt;
          }
          return std::move(loaded->mesh);
        } else if constexpr (std::is_same_v<S, PlaneSource>) {
          return make_plane_mesh(s.size_x_m, s.size_y_m);
        } else if constexpr (std::is_same_v<S, SphereSource>) {
          return make_sphere_mesh(s.radius_m, s.subdivisions);
        } else if constexpr (std::is_same_v<S, BoxSource>) {
          return make_box_mesh(s.size_m);
        } else if constexpr (std::is_same_v<S, CapsuleSource>) {
          return make_capsule_mesh(s.radius_m, s.length_m, capsule_rings(s.segments), s.segments);
        } else {
          return make_cylinder_mesh(s.radius_m, s.height_m, s.segments);
        }
      },
      shape);
}

}  // namespace

osg::ref_ptr<osg::Geometry> mesh_geometry(const TriangleMesh& mesh, const Eigen::Vector4f& rgba, std::string& reason) {
  if (mesh.triangles.empty()) {
    reason = "it has no triangles";
    return nullptr;
  }
  if (mesh.vertices_m.size() > std::numeric_limits<std::uint32_t>::max()) {
    reason = fmt::format("it has {} vertices, more than 32-bit indices address", mesh.vertices_m.size());
    return nullptr;
  }
  for (const TriangleIndices& t : mesh.triangles) {
    for (const std::uint32_t index : t) {
      if (index >= mesh.vertices_m.size()) {
        reason = fmt::format("a triangle names vertex {} of {}", index, mesh.vertices_m.size());
        return nullptr;
      }
    }
  }
  TriangleMesh with_normals;
  const TriangleMesh* m = &mesh;
  if (mesh.vertex_normals.size() != mesh.vertices_m.size()) {
    with_normals = mesh;
    compute_vertex_normals(with_normals);
    m = &with_normals;
  }
  auto vertices = make_ref<osg::Vec3Array>();
  auto normals = make_ref<osg::Vec3Array>();
  vertices->reserve(m->vertices_m.size());
  normals->reserve(m->vertices_m.size());
  constexpr double kFloatMax = static_cast<double>(std::numeric_limits<float>::max());
  for (std::size_t i = 0; i < m->vertices_m.size(); ++i) {
    const Eigen::Vector3d& v = m->vertices_m[i];
    if (!v.allFinite() || v.cwiseAbs().maxCoeff() > kFloatMax) {
      reason = fmt::format("vertex {} is not a finite single-precision point", i);
      return nullptr;
    }
    vertices->push_back(to_osg(v));
    normals->push_back(to_osg(m->vertex_normals[i]));
  }
  auto indices = make_ref<osg::DrawElementsUInt>(static_cast<GLenum>(GL_TRIANGLES));
  indices->reserve(m->triangles.size() * 3);
  for (const TriangleIndices& t : m->triangles) {
    for (const std::uint32_t index : t) indices->push_back(index);
  }
  auto geometry = make_ref<osg::Geometry>();
  geometry->setUseVertexBufferObjects(true);
  geometry->setVertexArray(vertices.get());
  geometry->setNormalArray(normals.get(), osg::Array::BIND_PER_VERTEX);
  auto colours = make_ref<osg::Vec4Array>();
  colours->push_back(osg::Vec4(rgba.x(), rgba.y(), rgba.z(), rgba.w()));
  geometry->setColorArray(colours.get(), osg::Array::BIND_OVERALL);
  geometry->addPrimitiveSet(indices.get());
  return geometry;
}

Result<SceneGraph, std::vector<std::string>> build_scene_graph(const SceneDescription& scene) {
  SceneGraph result;
  std::vector<std::string> errors;
  result.root = make_ref<osg::Group>();
  osg::StateSet* state = result.root->getOrCreateStateSet();
  // Planes and open meshes are seen from both sides; vertex colours drive the material.
  auto light_model = make_ref<osg::LightModel>();
  light_model->setTwoSided(true);
  // The headlight alone leaves surfaces seen at a grazing angle (the floor) black.
  light_model->setAmbientIntensity(osg::Vec4(0.35f, 0.35f, 0.35f, 1.0f));
  state->setAttributeAndModes(light_model.get());
  auto material = make_ref<osg::Material>();
  material->setColorMode(osg::Material::AMBIENT_AND_DIFFUSE);
  material->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.15f, 0.15f, 0.15f, 1.0f));
  material->setShininess(osg::Material::FRONT_AND_BACK, 24.0f);
  state->setAttributeAndModes(material.get());
  state->setMode(GL_NORMALIZE, osg::StateAttribute::ON);

  for (const ObjectDescription& object : scene.objects) {
    std::string error;
    const std::optional<TriangleMesh> mesh = shape_mesh(object.shape, error);
    if (!mesh) {
      errors.push_back(fmt::format("object '{}': {}", object.name, error));
      result.object_transforms.emplace_back();
      continue;
    }
    std::string reason;
    const osg::ref_ptr<osg::Geometry> geometry =
        mesh_geometry(*mesh, material_colour(object.material_name, object.name), reason);
    if (!geometry) {
      errors.push_back(fmt::format("object '{}': OSG cannot draw its mesh: {}", object.name, reason));
      result.object_transforms.emplace_back();
      continue;
    }
    auto transform = make_ref<osg::MatrixTransform>(to_osg(object.X_WO));
    transform->setName(object.name);
    transform->addChild(geometry.get());
    if (std::holds_alternative<PlaneSource>(object.shape)) {
      // Keep the floor grid (drawn at the same height) in front of a floor plane.
      transform->getOrCreateStateSet()->setAttributeAndModes(make_ref<osg::PolygonOffset>(1.0f, 1.0f).get());
    } else {
      for (const Eigen::Vector3d& v : mesh->vertices_m) result.objects_bounds_W.extend(object.X_WO * v);
    }
    result.root->addChild(transform.get());
    result.object_transforms.push_back(transform);
  }
  if (!errors.empty()) return errors;
  return result;
}

osg::ref_ptr<osg::Node> floor_grid(double half_size_m, double major_m, double minor_m) {
  auto vertices = make_ref<osg::Vec3Array>();
  auto colours = make_ref<osg::Vec4Array>();
  const int n = static_cast<int>(std::lround(half_size_m / minor_m));
  const int major_every = std::max(1, static_cast<int>(std::lround(major_m / minor_m)));
  const auto h = static_cast<float>(half_size_m);
  constexpr float kLift = 0.001f;  // just above the floor plane
  for (int i = -n; i <= n; ++i) {
    const auto c = static_cast<float>(i * minor_m);
    const bool major = i % major_every == 0;
    const osg::Vec4 colour = major ? osg::Vec4(0.75f, 0.75f, 0.75f, 1.0f) : osg::Vec4(0.47f, 0.48f, 0.50f, 1.0f);
    for (const auto& [a, b] : {std::pair{osg::Vec3(c, kLift, -h), osg::Vec3(c, kLift, h)},
                               std::pair{osg::Vec3(-h, kLift, c), osg::Vec3(h, kLift, c)}}) {
      vertices->push_back(a);
      vertices->push_back(b);
      colours->push_back(colour);
      colours->push_back(colour);
    }
  }
  auto geometry = make_ref<osg::Geometry>();
  geometry->setVertexArray(vertices.get());
  geometry->setColorArray(colours.get(), osg::Array::BIND_PER_VERTEX);
  geometry->addPrimitiveSet(new osg::DrawArrays(GL_LINES, 0, static_cast<GLsizei>(vertices->size())));
  osg::StateSet* state = geometry->getOrCreateStateSet();
  state->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
  state->setAttributeAndModes(make_ref<osg::LineWidth>(1.0f).get());
  auto group = make_ref<osg::Group>();
  group->setName("floor_grid");
  group->addChild(geometry.get());
  return group;
}

}  // namespace mhd::viewer
