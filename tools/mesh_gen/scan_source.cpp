#include "mesh_gen/scan_source.h"

#include "mesh_gen/bowl_mesh.h"
#include "mesh_gen/dolphin_mesh.h"
#include "mesh_gen/uv_sphere_mesh.h"
#include "mesh_io/mesh_loader.h"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace mhd::mesh_gen {
namespace {

constexpr double kBowlRadius_m = 0.150;
constexpr double kSphereRadius_m = 0.100;
constexpr double kDefaultFileUnit_m = 0.001;
constexpr std::size_t kMinGeneratorTriangles = 500;  // the dolphin's smallest

TriangleMesh make_generated(const std::string& name, std::size_t triangles) {
  if (name == "dolphin") return make_dolphin(dolphin_layout(triangles));
  if (name == "bowl") {
    const double cap_rad = 0.5 * std::numbers::pi;
    return make_bowl(kBowlRadius_m, cap_rad, bowl_layout(triangles, cap_rad));
  }
  return make_uv_sphere(kSphereRadius_m, uv_sphere_layout(triangles));
}

}  // namespace

std::string scan_source_names() { return "dolphin, bowl, uv-sphere"; }

TriangleMesh load_scan_source(const std::string& source, const ScanSourceOptions& options) {
  if (source == "dolphin" || source == "bowl" || source == "uv-sphere") {
    if (options.file_unit_m) {
      throw std::invalid_argument("scan source '" + source + "' is generated in metres: a file unit applies to mesh files only");
    }
    if (options.generator_triangles < kMinGeneratorTriangles) {
      throw std::invalid_argument("scan source '" + source + "' needs at least " + std::to_string(kMinGeneratorTriangles) +
                                  " triangles (got " + std::to_string(options.generator_triangles) + ")");
    }
    return make_generated(source, options.generator_triangles);
  }
  const std::filesystem::path file(source);
  if (!file.has_parent_path() && !file.has_extension()) {
    throw std::invalid_argument("unknown scan source '" + source + "' (expected " + scan_source_names() +
                                " or a mesh file path)");
  }
  const double unit_m = options.file_unit_m.value_or(kDefaultFileUnit_m);
  if (!(unit_m > 0.0) || !std::isfinite(unit_m)) {
    throw std::invalid_argument("scan source '" + source + "': the file unit must be a finite length > 0 m");
  }
  Result<LoadedMesh, MeshLoadError> loaded = load_mesh_file(file, Eigen::Vector3d::Constant(unit_m));
  if (!loaded.ok()) throw std::runtime_error(loaded.error().message());
  return std::move(loaded->mesh);
}

}  // namespace mhd::mesh_gen
