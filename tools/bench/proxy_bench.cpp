// mhd-proxy-bench: the stroke protocol (docs/benchmarks.md) on each benchmark scene. 200 random strokes
// at 0.5 m/s and 1 kHz; per-update times (median / p99 / p99.9 / max, one core) over the
// ticks in contact and over all ticks (free-space transit included), the ticks that ran
// out of the proxy's work budget, the most sweeps in one tick, and the exact pop-through
// count, and the look-ahead between ticks timed apart (--no-look-ahead: none). Prints a
// Markdown table. --force-shading shades every object, for the cost of shading.
// --hip-path drives every scene along one recorded path (--write-path's) and times the
// ticks only: no oracle is built, so meshes too large for it (100 M triangles) can be set
// beside a smaller mesh of the same shape in one run; nothing is judged there.
// --lock-meshes locks each scene's meshes in RAM first, as `mhd run --lock-meshes` does.
// With --hip-path, locked or not, the page faults the stepping thread took are printed
// on stderr.

#include "mesh_io/mesh_memory_lock.h"
#include "recording/hip_path_csv.h"
#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"
#include "stress/tour_transit.h"
#include "verification/stroke_run.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace {

// The stroke protocol's continuous path: the strokes joined, never reset, by moves
// through free space round and behind the object at the strokes' speed. A join leaves
// along the last stroke's surface normal to a sphere round the object, follows the
// sphere and comes in along the next stroke's normal; if a leg of that touches the
// surface (checked exactly), the stress tool's transit planner (5 mm clearance) is
// asked instead, and a stroke with no free join is left out (counted).
// Where a stroke can be left for free space: its last sample outside every closed object
// and 5 mm clear (a slide over a curved closed mesh can end inside it).
std::size_t last_free_sample(const mhd::verify::SurfaceCrossingOracle& oracle, const mhd::verify::Stroke& stroke) {
  for (std::size_t k = stroke.p_W_hip.size(); k-- > 0;) {
    const Eigen::Vector3d& p = stroke.p_W_hip[k];
    if (!oracle.point_inside_closed_mesh(p) && oracle.distance_to_surface(p) >= 0.005) return k;
  }
  return 0;
}

std::vector<Eigen::Vector3d> sphere_join(const mhd::verify::SurfaceCrossingOracle& oracle, const Eigen::Vector3d& centre,
                                         double radius, const Eigen::Vector3d& e, const mhd::verify::Stroke& from,
                                         const mhd::verify::Stroke& to) {
  auto out_to_sphere = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
    // p + t n with |p + t n - c| = radius, t > 0.
    const Eigen::Vector3d d = p - centre;
    const double b = n.dot(d);
    const double t = -b + std::sqrt(std::max(0.0, b * b - d.squaredNorm() + radius * radius));
    return Eigen::Vector3d(p + t * n);
  };
  const Eigen::Vector3d& s = to.p_W_hip.front();
  const Eigen::Vector3d a = out_to_sphere(e, from.anchor.normal_W);
  const Eigen::Vector3d b = out_to_sphere(s, to.anchor.normal_W);
  if (oracle.segment_touches_surface(e, a) || oracle.segment_touches_surface(b, s)) return {};
  std::vector<Eigen::Vector3d> corners{e, a};
  const double angle = std::acos(std::clamp((a - centre).normalized().dot((b - centre).normalized()), -1.0, 1.0));
  const int steps = std::max(1, static_cast<int>(std::ceil(angle / 0.1)));
  for (int i = 1; i < steps; ++i) {
    const Eigen::Vector3d m = a + (b - a) * (static_cast<double>(i) / steps);
    // Slerp-free: nudge the chord's points out to the sphere (a chord of 0.1 rad stays outside the
    // bounding sphere the radius was chosen against).
    corners.push_back(centre + radius * (m - centre).normalized());
  }
  corners.push_back(b);
  corners.push_back(s);
  return corners;
}

mhd::verify::StrokeSet join_in_free_space(const mhd::verify::SurfaceCrossingOracle& oracle,
                                         const mhd::verify::StrokeSet& set, std::uint64_t seed, double speed,
                                         double rate, std::size_t& skipped) {
  const mhd::stress::TourParams transit_params;
  Eigen::AlignedBox3d bounds;
  for (std::size_t i = 0; i < oracle.triangle_count(); ++i) {
    for (const auto& v : oracle.triangle_W(i)) bounds.extend(v);
  }
  // 10 mm outside the bounding sphere, so the chords between sphere points stay clear too.
  const double radius = 0.5 * bounds.diagonal().norm() + 0.03;
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  mhd::verify::Stroke path;
  const mhd::verify::Stroke* last = nullptr;
  for (const auto& stroke : set.strokes) {
    if (last != nullptr) {
      std::vector<Eigen::Vector3d> corners = sphere_join(oracle, bounds.center(), radius, path.p_W_hip.back(), *last, stroke);
      if (corners.empty()) {
        mhd::stress::TransitRequest request;
        request.from.p_W = path.p_W_hip.back();
        request.to.p_W = stroke.p_W_hip.front();
        request.bounds_W = bounds;
        request.around = 0.5 * bounds.diagonal().norm() <= transit_params.max_around_radius_m;
        if (const auto transit = mhd::stress::plan_free_transit(oracle, request, transit_params, rng)) {
          corners = transit->corners_W;
        }
      }
      if (corners.empty()) {
        ++skipped;
        continue;
      }
      const auto legs = mhd::verify::sample_polyline(corners, speed, rate);
      path.p_W_hip.insert(path.p_W_hip.end(), legs.begin() + 1, legs.end() - 1);
    }
    const auto end = stroke.p_W_hip.begin() + static_cast<std::ptrdiff_t>(last_free_sample(oracle, stroke)) + 1;
    path.stroke_starts.push_back(path.p_W_hip.size());
    path.p_W_hip.insert(path.p_W_hip.end(), stroke.p_W_hip.begin(), end);
    last = &stroke;
  }
  mhd::verify::StrokeSet joined;
  joined.strokes.push_back(std::move(path));
  return joined;
}

// The HIP path as `mhd proxy-replay --hip-csv` reads it: one row per tick at `rate`.
bool write_hip_csv(const std::filesystem::path& file, const mhd::verify::StrokeSet& set, double rate) {
  std::ofstream out(file);
  out << "t_s,x_m,y_m,z_m\n";
  std::size_t tick = 0;
  for (const auto& stroke : set.strokes) {
    for (const auto& p : stroke.p_W_hip) {
      out << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}\n", static_cast<double>(tick++) / rate, p.x(), p.y(), p.z());
    }
  }
  return static_cast<bool>(out);
}

// One row of the table; the exact counts read "not judged" where no oracle ran.
void print_row(const std::string& name, std::size_t triangles, const mhd::verify::StrokeRunReport& r,
               bool no_look_ahead, bool judged) {
  const auto& c = r.contact_updates;
  const auto& a = r.all_updates;
  const auto& l = r.look_ahead_updates;
  const std::string look_ahead =
      no_look_ahead ? std::string("off")
                    : fmt::format("{:.2f} / {:.2f} / {:.2f} / {:.1f}", l.median_us, l.p99_us, l.p999_us, l.max_us);
  const auto count = [&](std::size_t n) { return judged ? fmt::format("{}", n) : std::string("not judged"); };
  fmt::print("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {} | {} "
             "| {} | {} | {} | {} | {} |\n",
             name, triangles, c.count, c.median_us, c.p99_us, c.p999_us, c.max_us, a.count, a.median_us, a.p99_us,
             a.p999_us, a.max_us, r.budget_exhausted_ticks, r.max_sweeps, r.max_plane_count, count(r.pop_throughs),
             count(r.ticks_inside), count(r.follow_failures), look_ahead);
  std::fflush(stdout);
}

// A recorded HIP path as one stroke, or nullopt after printing the file's problem.
std::optional<mhd::verify::StrokeSet> read_hip_path(const std::string& file) {
  mhd::HipPathCsvReader reader{std::filesystem::path(file)};
  mhd::verify::Stroke path;
  while (const auto sample = reader.next()) path.p_W_hip.push_back(sample->p_W_hip_m);
  if (reader.error()) {
    fmt::print(stderr, "{}\n", reader.error()->to_string());
    return std::nullopt;
  }
  mhd::verify::StrokeSet set;
  set.strokes.push_back(std::move(path));
  return set;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenes = {"scenes/benchmarks/dolphin_3k.xml", "scenes/benchmarks/bunny.xml",
                                     "scenes/benchmarks/dolphin_100k.xml", "scenes/benchmarks/dolphin_1m.xml",
                                     "scenes/benchmarks/uv_sphere_1m.xml", "scenes/benchmarks/scan_dolphin.xml",
                                     "scenes/benchmarks/scan_bunny.xml",   "scenes/benchmarks/scan_bowl.xml"};
  int strokes = 200;
  std::uint64_t seed = 1;
  double speed = 0.5;
  double rate = 1000.0;
  CLI::App app{"Proxy update benchmark over the stroke protocol of docs/benchmarks.md", "mhd-proxy-bench"};
  app.add_option("scenes", scenes, "Scene files (default: scenes/benchmarks/*)");
  app.add_option("--strokes", strokes, "Strokes per scene");
  app.add_option("--seed", seed, "Stroke seed");
  app.add_option("--speed-mps", speed, "Stroke speed, m/s");
  app.add_option("--rate-hz", rate, "Update rate, Hz");
  bool reset_each = false;
  app.add_flag("--reset-each-stroke", reset_each,
               "Reset the proxy before each stroke instead of joining the strokes by free-space moves");
  bool shade_all = false;
  app.add_flag("--force-shading", shade_all,
               "Turn force shading on for every object (at its material's crease angle), to set its cost beside "
               "the same run without");
  bool no_look_ahead = false;
  app.add_flag("--no-look-ahead", no_look_ahead,
               "Do not look ahead between ticks (the haptic server does, proxy/proxy_look_ahead.h): the ticks as "
               "they cost with only what the last tick left in the cache");
  std::string path_dir;
  app.add_option("--write-path", path_dir,
                 "Also write each scene's HIP path to DIR/<scene>.csv, for mhd proxy-replay (before/after checks)");
  std::string hip_path;
  auto* hip_path_option =
      app.add_option("--hip-path", hip_path,
                     "Drive every scene along this HIP path (a --write-path file) and time the ticks only: no "
                     "exact oracle is built, and pop-throughs, ticks inside and follow failures are not judged");
  hip_path_option->excludes("--write-path")->excludes("--reset-each-stroke");
  bool lock_meshes = false;
  app.add_flag("--lock-meshes", lock_meshes,
               "Lock each scene's meshes in RAM before stepping (mhd run --lock-meshes): no tick then waits on a "
               "page fault of theirs");
  CLI11_PARSE(app, argc, argv);
  std::optional<mhd::verify::StrokeSet> given_path;
  if (!hip_path.empty()) {
    given_path = read_hip_path(hip_path);
    if (!given_path) return 1;
  }

  fmt::print("| scene | triangles | contact updates | median µs | p99 µs | p99.9 µs | max µs | all updates "
             "| all median µs | all p99 µs | all p99.9 µs | all max µs | budget exhausted | max sweeps "
             "| max planes | pop-throughs | ticks inside | follow failures "
             "| look-ahead median / p99 / p99.9 / max µs |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int status = 0;
  for (const auto& file : scenes) {
    const auto read = mhd::read_scene_file(file);
    if (!read.ok()) {
      for (const auto& d : read.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
      status = 1;
      continue;
    }
    mhd::SceneDescription description = *read;
    if (shade_all) {
      for (auto& object : description.objects) object.material.force_shading = true;
    }
    const auto compiled = mhd::compile_scene(description);
    if (!compiled.ok()) {
      for (const auto& d : compiled.diagnostics()) fmt::print(stderr, "{}\n", d.to_string());
      status = 1;
      continue;
    }
    const auto& scene = *compiled.value();
    const std::string name = shade_all ? file + " (shaded)" : file;
    mhd::PageLock locked;
    if (lock_meshes) {
      locked = mhd::lock_pages(mhd::mesh_memory_blocks(scene.world));
      if (locked.error) {
        fmt::print(stderr, "{}: {}\n", name, *locked.error);
        status = 1;
        continue;
      }
    }
    if (given_path) {
      const auto r = mhd::verify::time_strokes(scene, *given_path, rate, !no_look_ahead);
      print_row(name, scene.triangle_count, r, no_look_ahead, false);
      fmt::print(stderr, "{}: page faults while stepping: {} minor, {} major; meshes locked in RAM: {:.1f} MiB\n", name,
                 r.minor_page_faults, r.major_page_faults, static_cast<double>(locked.pages.bytes()) / (1U << 20));
      continue;
    }
    const mhd::verify::SurfaceCrossingOracle oracle(scene.world);
    mhd::verify::AnchorStrokeParams params;
    params.speed_m_per_s = speed;
    params.rate_Hz = rate;
    const auto anchors = mhd::verify::make_anchor_strokes(oracle, seed, strokes, params);
    std::size_t skipped = 0;
    const auto set = reset_each ? anchors : join_in_free_space(oracle, anchors, seed, speed, rate, skipped);
    if (skipped > 0) fmt::print(stderr, "{}: {} strokes left out (no free transit found)\n", file, skipped);
    if (!path_dir.empty()) {
      const auto csv = std::filesystem::path(path_dir) / (std::filesystem::path(file).stem().string() + ".csv");
      if (!write_hip_csv(csv, set, rate)) {
        fmt::print(stderr, "{}: cannot write {}\n", file, csv.string());
        status = 1;
      }
    }
    const auto r = mhd::verify::run_strokes(scene, oracle, set, rate, !no_look_ahead);
    print_row(name, scene.triangle_count, r, no_look_ahead, true);
    fmt::print(stderr, "{}: held behind a surface on {} ticks; {} of {} strokes started behind\n", name, r.held_ticks,
               r.strokes_starting_behind, r.strokes_begun);
    if (r.pop_throughs != 0 || r.ticks_inside != 0 || r.follow_failures != 0) status = 1;
  }
  return status;
}
