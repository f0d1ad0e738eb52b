#include "scene_compiler/scene_compiler.h"

#include "dynamics/body_shape.h"
#include "geometry/primitive_mesh.h"
#include "geometry/shading_normals.h"
#include "mesh_io/available_memory.h"
#include "mesh_io/mesh_cache.h"
#include "scene_compiler/exact_primitive.h"
#include "scene_compiler/texture_compiler.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <exception>
#include <map>
#include <numbers>
#include <string>
#include <system_error>
#include <utility>
#include <variant>
#include <vector>

namespace mhd {
namespace {

/// Highest cylinder tessellation accepted (far beyond anything a hand can feel).
constexpr int kMaxCylinderSegments = 1 << 16;

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }

Diagnostic make_diagnostic(const SourceLocation& where, std::string message) {
  Diagnostic d;
  d.where = where;
  d.message = std::move(message);
  return d;
}

SourceLocation file_location(const std::filesystem::path& file) {
  SourceLocation where;
  where.file = file.string();
  return where;
}

template <class... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

/// Identity of a mesh source: the file (symlinks and ".." resolved where possible) and
/// the exact scale.
using MeshKey = std::pair<std::string, std::array<std::uint64_t, 3>>;

MeshKey mesh_key(const MeshSource& source) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::weakly_canonical(source.file, ec);
  if (ec) p = source.file.lexically_normal();
  return {p.string(),
          {std::bit_cast<std::uint64_t>(source.scale_to_m.x() + 0.0), std::bit_cast<std::uint64_t>(source.scale_to_m.y() + 0.0),
           std::bit_cast<std::uint64_t>(source.scale_to_m.z() + 0.0)}};
}

/// A shape shared by every object that names the same source.
struct SharedShape {
  std::shared_ptr<const MeshBvh> bvh;
  std::string error;  ///< set instead of bvh when the source cannot be used
};

class Compiler {
 public:
  Compiler(const SceneDescription& description, const CompileOptions& options)
      : description_(description),
        options_(options),
        cache_(options.use_cache ? (options.cache_dir ? options.cache_dir : default_mesh_cache_dir())
                                 : std::nullopt) {}

  Result<std::unique_ptr<CompiledScene>> run() {
    Diagnostics errors;
    const auto& objects = description_.objects;
    std::vector<std::shared_ptr<const MeshBvh>> shapes(objects.size());
    std::vector<std::shared_ptr<const HapticTexture>> textures(objects.size());

    const std::optional<double>& max_force_N = description_.haptics.max_force_N;
    if (max_force_N && !positive_finite(*max_force_N)) {
      errors.push_back(make_diagnostic(
          file_location(description_.file),
          fmt::format("haptics: max force must be positive and finite (got {} N)", *max_force_N)));
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const ObjectDescription& object = objects[i];
      std::string error = check_pose(object.X_WO);
      if (error.empty()) error = check_shading(object.material);
      if (error.empty()) {
        try {
          const SharedShape& shape = shape_for(object);
          if (shape.bvh) {
            shapes[i] = shape.bvh;
            // A pushable object is its mesh's convex hull: one with no volume cannot be one.
            if (object.dynamics) (void)make_body_hull(shape.bvh->mesh());
          } else {
            error = shape.error;
          }
        } catch (const std::exception& e) {
          error = e.what();
        }
      }
      if (!error.empty()) {
        errors.push_back(make_diagnostic(object.where, fmt::format("object '{}': {}", object.name, error)));
      }
      if (std::string texture_error = texture_for(object, textures[i]); !texture_error.empty()) {
        errors.push_back(
            make_diagnostic(object.where, fmt::format("object '{}': texture: {}", object.name, texture_error)));
      }
    }
    if (!errors.empty()) return errors;  // nothing half-loaded

    auto scene = std::make_unique<CompiledScene>();
    scene->name = description_.name;
    // With no device open, the scene's clamp or the thesis arm's; a run replaces it by
    // the device's (HapticTick).
    scene->proxy.max_force_N = description_.haptics.max_force_N.value_or(kNoDeviceMaxForce_N);
    scene->materials.reserve(objects.size());
    scene->object_names.reserve(objects.size());
    scene->motions.reserve(objects.size());
    scene->dynamics.reserve(objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const int id = scene->world.add_object(shapes[i], objects[i].X_WO);
      if (const auto exact = exact_shape_of(objects[i].shape)) scene->world.set_exact_shape(id, *exact);
      scene->world.set_touchable(id, objects[i].touchable);
      if (objects[i].material.force_shading) {
        scene->world.set_shading_normals(id, shading_normals_for(shapes[i], objects[i].material));
      }
      scene->materials.push_back(objects[i].material);
      if (textures[i]) scene->materials.back().texture = textures[i];
      scene->object_names.push_back(objects[i].name);
      scene->motions.push_back(objects[i].motion);
      scene->dynamics.push_back(objects[i].dynamics);
      scene->triangle_count += shapes[i]->mesh().triangle_count();
    }
    scene->world.index_objects();
    scene->sharing = compile_sharing(description_);
    const auto& stats = cache_.stats();
    spdlog::debug("compiled scene '{}': {} objects, {} triangles, {} distinct shapes (mesh cache: {} hits, {} misses, "
                  "{} rejected)",
                  scene->name, objects.size(), scene->triangle_count, meshes_.size() + primitives_.size(),
                  stats.hits, stats.misses, stats.rejected);
    return scene;
  }

 private:
  // The scene reader has checked the declarations (scene_xml/sharing_reader.h): each
  // object exists, once, with an id of its own and at most kMaxAuthorityRigs rigs.
  static std::optional<CompiledSharing> compile_sharing(const SceneDescription& description) {
    if (!description.sharing) return std::nullopt;
    CompiledSharing out;
    out.rig_id = description.sharing->rig_id;
    for (const SharedObjectDescription& d : description.sharing->objects) {
      SharedObjectDeclaration c;
      c.id = d.id;
      for (std::size_t i = 0; i < description.objects.size(); ++i) {
        if (description.objects[i].name == d.object) c.object = static_cast<int>(i);
      }
      c.rig_count = static_cast<int>(std::min(d.rigs.size(), c.rigs.size()));
      std::copy_n(d.rigs.begin(), c.rig_count, c.rigs.begin());
      out.objects.push_back(c);
    }
    return out;
  }

  static std::string check_pose(const Pose& X_WO) {
    if (!X_WO.matrix().allFinite()) return "pose is not finite";
    const Eigen::Matrix3d R = X_WO.linear();
    if (!(R.transpose() * R).isIdentity(1e-9) || R.determinant() < 0.0) return "pose rotation is not a rotation";
    return {};
  }

  /// The object's texture (built once per named material), or its material's own (set
  /// in code), or none; "" or why it cannot be built.
  std::string texture_for(const ObjectDescription& object, std::shared_ptr<const HapticTexture>& texture) {
    const HapticMaterial& material = object.material;
    if (material.texture || !material.texture_spec) return {};
    if (!object.material_name.empty()) {
      if (const auto it = named_textures_.find(object.material_name); it != named_textures_.end()) {
        texture = it->second;
        return {};
      }
    }
    std::string error = compile_texture(*material.texture_spec, texture);
    if (error.empty() && !object.material_name.empty()) named_textures_.emplace(object.material_name, texture);
    return error;
  }

  static std::string check_shading(const HapticMaterial& m) {
    const double crease = m.force_shading_crease_rad;
    if (!(crease >= 0.0 && crease <= std::numbers::pi)) {
      return fmt::format("force shading crease angle must be within [0, pi] rad (got {} rad)", crease);
    }
    return {};
  }

  /// Crease-aware corner normals for a shaded material, shared by the objects that use
  /// the same shape with the same crease angle.
  std::shared_ptr<const ShadingNormals> shading_normals_for(const std::shared_ptr<const MeshBvh>& shape,
                                                            const HapticMaterial& material) {
    const ShadingKey key{shape.get(), std::bit_cast<std::uint64_t>(material.force_shading_crease_rad + 0.0)};
    auto& normals = shading_normals_[key];
    if (!normals) {
      normals = std::make_shared<const ShadingNormals>(
          compute_shading_normals(shape->mesh(), material.force_shading_crease_rad));
    }
    return normals;
  }

  /// Reports progress for `object` (no-op without a callback).
  MeshProgress progress_for(const ObjectDescription& object) const {
    if (!options_.progress) return {};
    return [this, name = object.name](std::string_view what, double fraction) {
      options_.progress(fmt::format("object '{}': {}", name, what), fraction);
    };
  }

  const SharedShape& shape_for(const ObjectDescription& object) {
    return std::visit(
        Overloaded{
            [&](const MeshSource& s) -> const SharedShape& { return mesh_shape(object, s); },
            [&](const PlaneSource& s) -> const SharedShape& {
              if (!positive_finite(s.size_x_m) || !positive_finite(s.size_y_m)) {
                return invalid(fmt::format("plane size must be positive and finite (got {} x {} m)", s.size_x_m,
                                           s.size_y_m));
              }
              return primitive(object, fmt::format("plane {:a} {:a}", s.size_x_m, s.size_y_m),
                               [&] { return make_plane_mesh(s.size_x_m, s.size_y_m); });
            },
            [&](const SphereSource& s) -> const SharedShape& {
              if (!positive_finite(s.radius_m)) {
                return invalid(fmt::format("sphere radius must be positive and finite (got {} m)", s.radius_m));
              }
              if (s.subdivisions < 0 || s.subdivisions > 7) {
                return invalid(fmt::format("sphere subdivisions must be 0..7 (got {})", s.subdivisions));
              }
              return primitive(object, fmt::format("sphere {:a} {}", s.radius_m, s.subdivisions),
                               [&] { return make_sphere_mesh(s.radius_m, s.subdivisions); });
            },
            [&](const BoxSource& s) -> const SharedShape& {
              if (!positive_finite(s.size_m.x()) || !positive_finite(s.size_m.y()) || !positive_finite(s.size_m.z())) {
                return invalid(fmt::format("box size must be positive and finite (got {} x {} x {} m)", s.size_m.x(),
                                           s.size_m.y(), s.size_m.z()));
              }
              return primitive(object, fmt::format("box {:a} {:a} {:a}", s.size_m.x(), s.size_m.y(), s.size_m.z()),
                               [&] { return make_box_mesh(s.size_m); });
            },
            [&](const CapsuleSource& s) -> const SharedShape& {
              if (!positive_finite(s.radius_m) || !positive_finite(s.length_m)) {
                return invalid(fmt::format("capsule radius and length must be positive and finite (got {} m, {} m)",
                                           s.radius_m, s.length_m));
              }
              if (s.segments < 3 || s.segments > kMaxCylinderSegments) {
                return invalid(
                    fmt::format("capsule segments must be 3..{} (got {})", kMaxCylinderSegments, s.segments));
              }
              return primitive(object, fmt::format("capsule {:a} {:a} {}", s.radius_m, s.length_m, s.segments), [&] {
                return make_capsule_mesh(s.radius_m, s.length_m, capsule_rings(s.segments), s.segments);
              });
            },
            [&](const CylinderSource& s) -> const SharedShape& {
              if (!positive_finite(s.radius_m) || !positive_finite(s.height_m)) {
                return invalid(fmt::format("cylinder radius and height must be positive and finite (got {} m, {} m)",
                                           s.radius_m, s.height_m));
              }
              if (s.segments < 3 || s.segments > kMaxCylinderSegments) {
                return invalid(
                    fmt::format("cylinder segments must be 3..{} (got {})", kMaxCylinderSegments, s.segments));
              }
              return primitive(object, fmt::format("cylinder {:a} {:a} {}", s.radius_m, s.height_m, s.segments),
                               [&] { return make_cylinder_mesh(s.radius_m, s.height_m, s.segments); });
            },
        },
        object.shape);
  }

  const SharedShape& invalid(std::string message) {
    invalid_ = SharedShape{nullptr, std::move(message)};
    return invalid_;
  }

  const SharedShape& mesh_shape(const ObjectDescription& object, const MeshSource& source) {
    const MeshKey key = mesh_key(source);
    if (const auto it = meshes_.find(key); it != meshes_.end()) return it->second;
    SharedShape shape;
    const TriangleBudget budget{description_.max_triangles, loaded_triangles_, available_memory_bytes()};
    const Result<CachedMesh, MeshLoadError> loaded =
        cache_.load(source.file, source.scale_to_m, progress_for(object), budget);
    if (loaded.ok()) {
      shape.bvh = loaded->bvh;
      loaded_triangles_ += loaded->mesh().triangle_count();
      if (loaded->dropped_triangles > 0) {
        spdlog::info("{}: mesh file '{}': dropped {} degenerate triangles", object.name, source.file.string(),
                     loaded->dropped_triangles);
      }
      if (loaded->flipped_triangles > 0) {
        spdlog::info("{}: mesh file '{}': turned {} triangles wound against the rest of their surface", object.name,
                     source.file.string(), loaded->flipped_triangles);
      }
      if (!loaded->unisolated_read.empty()) {
        spdlog::warn("{}: mesh file '{}': read by assimp in this process ({}); a crash or endless loop of its "
                     "reader would not have been contained",
                     object.name, source.file.string(), loaded->unisolated_read);
      }
    } else {
      shape.error = loaded.error().message();
    }
    return meshes_.emplace(key, std::move(shape)).first->second;
  }

  template <class Make>
  const SharedShape& primitive(const ObjectDescription& object, const std::string& key, Make&& make) {
    if (const auto it = primitives_.find(key); it != primitives_.end()) return it->second;
    auto mesh = std::make_shared<const TriangleMesh>(make());
    const TriangleBudget budget{description_.max_triangles, loaded_triangles_};
    if (std::string refused = budget.refusal("", mesh->triangle_count(), "triangles"); !refused.empty()) {
      return invalid(std::move(refused));
    }
    loaded_triangles_ += mesh->triangle_count();
    const bool report = options_.progress && mesh->triangle_count() >= kProgressMinTriangles;
    const MeshProgress progress = progress_for(object);
    const std::string what = fmt::format("building BVH ({} triangles)", mesh->triangle_count());
    if (report) progress(what, 0.0);
    SharedShape shape{std::make_shared<const MeshBvh>(std::move(mesh)), {}};
    if (report) progress(what, 1.0);
    return primitives_.emplace(key, std::move(shape)).first->second;
  }

  const SceneDescription& description_;
  const CompileOptions& options_;
  MeshCache cache_;
  std::map<MeshKey, SharedShape> meshes_;
  std::map<std::string, SharedShape> primitives_;
  std::map<std::string, std::shared_ptr<const HapticTexture>> named_textures_;  ///< by material name
  SharedShape invalid_;
  using ShadingKey = std::pair<const MeshBvh*, std::uint64_t>;  // shape, crease angle's bits
  std::map<ShadingKey, std::shared_ptr<const ShadingNormals>> shading_normals_;
  std::uint64_t loaded_triangles_ = 0;  ///< over distinct shapes, for max_triangles
};

}  // namespace

Result<std::unique_ptr<CompiledScene>> compile_scene(const SceneDescription& description,
                                                     const CompileOptions& options) {
  try {
    return Compiler(description, options).run();
  } catch (const std::exception& e) {
    return make_diagnostic(file_location(description.file), fmt::format("cannot compile scene: {}", e.what()));
  }
}

}  // namespace mhd
