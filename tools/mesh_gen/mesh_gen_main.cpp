// mhd-mesh-gen: writes the procedural test meshes (dolphin, UV sphere, bowl, range
// scans) in millimetres, the format chosen by the output file's extension.

#include "mesh_gen/bowl_mesh.h"
#include "mesh_gen/dolphin_mesh.h"
#include "mesh_gen/mesh_export.h"
#include "mesh_gen/range_scan.h"
#include "mesh_gen/scan_source.h"
#include "mesh_gen/uv_sphere_mesh.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <numbers>
#include <regex>
#include <stdexcept>
#include <string>
#include <utility>

namespace {

constexpr double kMillimetresPerMetre = 1000.0;

// One more triangle facing +z, `stray_m` past the mesh along +x: a mesh as users may have
// one, with a range scan's stray point or a part left at another origin. Its sides are 1 mm,
// or a millionth of the distance where a file's single-precision millimetres would not
// keep 1 mm apart.
void add_stray_triangle(mhd::TriangleMesh& mesh, double stray_m) {
  const Eigen::AlignedBox3d box = mhd::mesh_bounds(mesh);
  const Eigen::Vector3d at(box.max().x() + stray_m, box.center().y(), box.center().z());
  const auto first = static_cast<std::uint32_t>(mesh.vertices_m.size());
  const double side_m = std::max(0.001, 1e-6 * at.cwiseAbs().maxCoeff());
  mesh.vertices_m.push_back(at);
  mesh.vertices_m.push_back(at + Eigen::Vector3d(side_m, 0.0, 0.0));
  mesh.vertices_m.push_back(at + Eigen::Vector3d(0.0, side_m, 0.0));
  mesh.triangles.push_back({first, first + 1, first + 2});
}

// Winds about `percent` % of the triangles the other way, picked by a hash of their number
// (the same ones on every run): a file as some tools write them, with mixed windings.
// Returns how many.
std::size_t wind_some_the_other_way(mhd::TriangleMesh& mesh, double percent) {
  std::size_t wound = 0;
  const double fraction = percent / 100.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    // splitmix64's finaliser: consecutive numbers spread over the whole range.
    std::uint64_t h = static_cast<std::uint64_t>(t) + 0x9E3779B97F4A7C15ULL;
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ULL;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBULL;
    h ^= h >> 31;
    if (static_cast<double>(h >> 11) * 0x1p-53 < fraction) {
      std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      ++wound;
    }
  }
  return wound;
}

// What is done to a made mesh before it is written: faults of meshes as users have them.
struct FileFaults {
  double stray_m = 0.0;
  double wrong_winding_percent = 0.0;
};

int write_and_report(mhd::TriangleMesh mesh, const std::string& out, std::chrono::steady_clock::time_point start,
                     const FileFaults& faults) {
  if (faults.stray_m > 0.0) add_stray_triangle(mesh, faults.stray_m);
  const std::size_t wound =
      faults.wrong_winding_percent > 0.0 ? wind_some_the_other_way(mesh, faults.wrong_winding_percent) : 0;
  const auto built = std::chrono::steady_clock::now();
  const std::filesystem::path file(out);
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  mhd::mesh_gen::write_mesh_file(mesh, file, kMillimetresPerMetre);
  const auto written = std::chrono::steady_clock::now();
  const Eigen::AlignedBox3d box = mhd::mesh_bounds(mesh);
  const Eigen::Vector3d size_mm = box.sizes() * kMillimetresPerMetre;
  using ms = std::chrono::duration<double, std::milli>;
  std::printf("%s: %zu triangles, %zu vertices, %.1f x %.1f x %.1f mm; built in %.0f ms, written in %.0f ms\n",
              out.c_str(), mesh.triangle_count(), mesh.vertices_m.size(), size_mm.x(), size_mm.y(), size_mm.z(),
              ms(built - start).count(), ms(written - built).count());
  if (wound > 0) std::printf("%s: %zu triangles wound the other way\n", out.c_str(), wound);
  return 0;
}

// "330x330" -> columns 330, rows 330.
void parse_grid(const std::string& text, mhd::mesh_gen::RangeScanParams& params) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,9})x(\d{1,9}))"))) {
    throw std::invalid_argument("--grid '" + text + "': expected COLUMNSxROWS, e.g. 330x330");
  }
  params.columns = std::stoi(m[1].str());
  params.rows = std::stoi(m[2].str());
}

int scan_and_report(const std::string& source, const mhd::mesh_gen::ScanSourceOptions& options,
                    mhd::mesh_gen::RangeScanParams params, const std::string& grid, const std::string& out,
                    std::chrono::steady_clock::time_point start, const FileFaults& faults) {
  parse_grid(grid, params);
  const mhd::TriangleMesh source_mesh = mhd::mesh_gen::load_scan_source(source, options);
  const mhd::mesh_gen::RangeScan scan = mhd::mesh_gen::make_range_scan(source_mesh, params);
  if (scan.mesh.triangles.empty()) throw std::runtime_error("range scan of '" + source + "' has no triangles");
  const mhd::mesh_gen::RangeScanStats& st = scan.stats;
  std::printf("range scan of %s (%zu triangles): %s samples at %.3f mm, %zu hit, %zu patches; dropped %zu "
              "triangles at depth jumps, %zu degenerate\n",
              source.c_str(), source_mesh.triangle_count(), grid.c_str(), st.spacing_m * kMillimetresPerMetre,
              st.samples_hit, st.patches, st.dropped_depth_jump, st.dropped_degenerate);
  return write_and_report(scan.mesh, out, start, faults);
}

}  // namespace

// The most a scene loads by default is 50 M; benchmarks of the collision tree go to
// 200 M and past it. The generators take about 35 bytes per triangle (3.5 GB peak for a
// 100 M sphere, /usr/bin/time -v), so 300 M fits a 24 GB machine.
constexpr std::size_t kMaxTriangles = 300'000'000;

int main(int argc, char** argv) {
  CLI::App app{"Writes MHD's procedural test meshes in millimetres (.ply binary, .obj or .stl)."};
  app.require_subcommand(1);
  double stray_mm = 0.0;
  app.add_option("--stray-triangle-mm", stray_mm,
                 "add one small triangle this far past the mesh along +x (a scan's stray point); give it before "
                 "the subcommand")
      ->check(CLI::NonNegativeNumber);
  double wrong_winding_percent = 0.0;
  app.add_option("--wrong-winding-percent", wrong_winding_percent,
                 "wind about this share of the triangles the other way, scattered (a file with mixed windings); "
                 "give it before the subcommand")
      ->check(CLI::Range(0.0, 100.0));

  std::size_t dolphin_triangles = 3000;
  std::string dolphin_out;
  CLI::App* dolphin = app.add_subcommand("dolphin", "closed bottlenose dolphin, 2000 mm from beak to fluke tips");
  dolphin->add_option("--triangles", dolphin_triangles, "target triangle count (met within 2 %)")
      ->check(CLI::Range(std::size_t{500}, kMaxTriangles));
  dolphin->add_option("--out", dolphin_out, "output file")->required();

  std::size_t sphere_triangles = 1'000'000;
  double sphere_radius_mm = 100.0;
  std::string sphere_out;
  CLI::App* sphere = app.add_subcommand("uv-sphere", "closed latitude/longitude sphere");
  sphere->add_option("--triangles", sphere_triangles, "target triangle count")
      ->check(CLI::Range(std::size_t{12}, kMaxTriangles));
  sphere->add_option("--radius-mm", sphere_radius_mm, "radius")->check(CLI::PositiveNumber);
  sphere->add_option("--out", sphere_out, "output file")->required();

  std::size_t bowl_triangles = 4000;
  double bowl_radius_mm = 150.0;
  double bowl_cap_deg = 90.0;
  std::string bowl_out;
  CLI::App* bowl = app.add_subcommand("bowl", "open single-layer spherical cap, opening upward (+y)");
  bowl->add_option("--triangles", bowl_triangles, "target triangle count")
      ->check(CLI::Range(std::size_t{8}, kMaxTriangles));
  bowl->add_option("--radius-mm", bowl_radius_mm, "sphere radius")->check(CLI::PositiveNumber);
  bowl->add_option("--cap-deg", bowl_cap_deg, "polar angle of the rim from the bottom (90: hemisphere)")
      ->check(CLI::Range(1.0, 179.0));
  bowl->add_option("--out", bowl_out, "output file")->required();

  std::string scan_source;
  mhd::mesh_gen::ScanSourceOptions scan_options;
  double scan_unit_m = 0.0;
  mhd::mesh_gen::RangeScanParams scan_params;
  double scan_noise_mm = 0.0;
  std::string scan_grid = "330x330";
  std::string scan_out;
  CLI::App* scan = app.add_subcommand(
      "range-scan", "open single-view range scan of a mesh: orthographic depth grid, cut at depth jumps");
  scan->add_option("--source", scan_source,
                   "what to scan: " + mhd::mesh_gen::scan_source_names() + " or a mesh file path")
      ->required();
  scan->add_option("--source-triangles", scan_options.generator_triangles, "triangles of a generated source");
  CLI::Option* unit = scan->add_option("--source-unit-m", scan_unit_m, "metres per unit of a mesh file (default 0.001)");
  scan->add_option("--azimuth-deg", scan_params.azimuth_deg, "scanner direction about +y, from +z towards +x");
  scan->add_option("--elevation-deg", scan_params.elevation_deg, "scanner direction above the x-z plane");
  scan->add_option("--grid", scan_grid, "samples, COLUMNSxROWS (square cells fitted to the source's outline)");
  scan->add_option("--max-jump-cells", scan_params.max_depth_jump_cells,
                   "drop triangles whose depths differ by more than this many grid spacings");
  scan->add_option("--noise-mm", scan_noise_mm, "uniform per-sample noise along the ray, [0, 1) mm");
  scan->add_option("--seed", scan_params.seed, "seed of the noise");
  scan->add_option("--out", scan_out, "output file")->required();

  CLI11_PARSE(app, argc, argv);

  try {
    const FileFaults faults{stray_mm / kMillimetresPerMetre, wrong_winding_percent};
    if (scan->parsed()) {
      (void)mhd::mesh_gen::mesh_file_format(scan_out);
      if (unit->count() > 0) scan_options.file_unit_m = scan_unit_m;
      scan_params.noise_m = scan_noise_mm / kMillimetresPerMetre;
      return scan_and_report(scan_source, scan_options, scan_params, scan_grid, scan_out,
                             std::chrono::steady_clock::now(), faults);
    }
    (void)mhd::mesh_gen::mesh_file_format(dolphin->parsed() ? dolphin_out : sphere->parsed() ? sphere_out : bowl_out);
    const auto start = std::chrono::steady_clock::now();
    if (dolphin->parsed()) {
      return write_and_report(mhd::mesh_gen::make_dolphin(mhd::mesh_gen::dolphin_layout(dolphin_triangles)),
                              dolphin_out, start, faults);
    }
    if (sphere->parsed()) {
      return write_and_report(mhd::mesh_gen::make_uv_sphere(sphere_radius_mm / kMillimetresPerMetre,
                                                             mhd::mesh_gen::uv_sphere_layout(sphere_triangles)),
                              sphere_out, start, faults);
    }
    const double cap_rad = bowl_cap_deg * std::numbers::pi / 180.0;
    return write_and_report(mhd::mesh_gen::make_bowl(bowl_radius_mm / kMillimetresPerMetre, cap_rad,
                                                     mhd::mesh_gen::bowl_layout(bowl_triangles, cap_rad)),
                            bowl_out, start, faults);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mhd-mesh-gen: %s\n", e.what());
    return 1;
  }
}
