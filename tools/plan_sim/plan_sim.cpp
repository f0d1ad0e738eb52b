#include "plan_sim.h"

#include "planner/planner_geometry.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <sstream>
#include <tuple>

namespace mhd::plan_sim {

namespace g = planner_geometry;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Vector3d hand_of(const Eigen::Vector2d& user, double heading, double reach) {
  const Eigen::Vector2d h = user + reach * g::direction(heading);
  return Eigen::Vector3d(h.x(), 1.1, h.y());
}

}  // namespace

CaseResult simulate_case(PlannerKind kind, const PlannerSettings& settings, const MapSpec& spec,
                         const Eigen::Vector2d& next_user_W) {
  const std::unique_ptr<Planner> planner = make_planner(kind, settings);
  const double reach = settings.arm_length_m;
  const Eigen::Vector2d start_user(0.0, 0.0);
  const Eigen::Vector2d start_base = g::follow_target(start_user, {reach, 0.0}, 0.0, settings.target_distance_m());
  BasePose base{start_base.x(), start_base.y(), g::facing_heading(start_base, start_user, settings.facing_angle_rad)};

  const double heading = spec.facing_change_rad;
  const Eigen::Vector3d hip = hand_of(next_user_W, heading, reach);
  const double r_collision = settings.collision_radius_m();
  const auto hip_inside = [&](const BasePose& b) {
    const Eigen::Vector2d p = g::hip_in_base(b, hip);
    return settings.usable_B.contains(p.x(), p.y());
  };

  CaseResult result;
  if (hip_inside(base)) {
    result.followed = true;
    return result;
  }
  const double period = settings.command_period_s;
  const int ticks = static_cast<int>(std::ceil(spec.horizon_s / period - 1e-9));
  for (int k = 0; k < ticks; ++k) {
    PlannerInput in;
    in.time_s = k * period;
    in.base = base;
    in.user_W = next_user_W;
    in.user_heading_rad = heading;
    in.p_W_hip = hip;
    const PlannerOutput out = planner->update(in);
    const double d_start = (Eigen::Vector2d(base.x_m, base.z_m) - next_user_W).norm();
    for (int i = 1; i <= spec.substeps; ++i) {
      const double dt = period * i / spec.substeps;
      if (in.time_s + dt > spec.horizon_s + 1e-9) break;
      const BasePose b = integrate_twist(base, out.twist_B, dt);
      const double d = (Eigen::Vector2d(b.x_m, b.z_m) - next_user_W).norm();
      if (d_start >= r_collision ? d < r_collision : d < d_start - 1e-12) result.base_entered = true;
      if (!result.followed && hip_inside(b)) {
        result.followed = true;
        result.time_s = in.time_s + dt;
      }
    }
    if (result.followed) break;
    base = integrate_twist(base, out.twist_B, period);
  }
  return result;
}

Eigen::Vector2d FollowMap::cell_center(int ix, int iz) const noexcept {
  return Eigen::Vector2d(-half_size_m + (ix + 0.5) * cell_m, -half_size_m + (iz + 0.5) * cell_m);
}

FollowMap simulate_map(PlannerKind kind, const PlannerSettings& settings, const MapSpec& spec) {
  FollowMap map;
  map.half_size_m = spec.half_size_m;
  map.cell_m = spec.cell_m;
  map.cells_per_side = static_cast<int>(std::lround(2.0 * spec.half_size_m / spec.cell_m));
  map.followed.assign(static_cast<std::size_t>(map.cells_per_side) * static_cast<std::size_t>(map.cells_per_side), 0);
  for (int iz = 0; iz < map.cells_per_side; ++iz) {
    for (int ix = 0; ix < map.cells_per_side; ++ix) {
      const CaseResult r = simulate_case(kind, settings, spec, map.cell_center(ix, iz));
      if (r.followed) {
        map.followed[static_cast<std::size_t>(iz * map.cells_per_side + ix)] = 1;
        ++map.followed_cells;
      }
      if (r.base_entered) ++map.base_entries;
    }
  }
  return map;
}

std::string table_csv(const std::vector<TableRow>& rows) {
  std::ostringstream out;
  out << "planner,facing_change_deg,max_linear_speed_mps,max_angular_speed_degps,followed_cells,followed_area_m2,"
         "base_entries\n";
  for (const TableRow& r : rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%.0f,%.2f,%.0f,%d,%.4f,%d\n", std::string(to_string(r.kind)).c_str(),
                  r.facing_change_rad / kDeg, r.max_linear_speed_mps, r.max_angular_speed_radps / kDeg,
                  r.followed_cells, r.followed_area_m2, r.base_entries);
    out << line;
  }
  return out.str();
}

std::string table_text(const std::vector<TableRow>& rows) {
  // (facing, v, omega) -> area per planner.
  using Key = std::tuple<long, long, long>;
  std::map<Key, std::map<PlannerKind, double>> cells;
  std::vector<long> facings, speeds, omegas;
  const auto add = [](std::vector<long>& v, long x) {
    if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
  };
  for (const TableRow& r : rows) {
    const long f = std::lround(r.facing_change_rad / kDeg);
    const long v = std::lround(r.max_linear_speed_mps * 100.0);
    const long w = std::lround(r.max_angular_speed_radps / kDeg);
    add(facings, f);
    add(speeds, v);
    add(omegas, w);
    cells[{f, v, w}][r.kind] = r.followed_area_m2;
  }
  std::ostringstream out;
  char buf[128];
  for (const long f : facings) {
    out << "followed area [m^2] within 1 s, user's facing change " << f << " deg\n";
    out << "  v_max  |";
    for (const long w : omegas) {
      std::snprintf(buf, sizeof buf, "  %3ld deg/s: seed  pred  ratio |", w);
      out << buf;
    }
    out << "\n";
    for (const long v : speeds) {
      std::snprintf(buf, sizeof buf, "  %.1f m/s|", static_cast<double>(v) / 100.0);
      out << buf;
      for (const long w : omegas) {
        const auto& c = cells[{f, v, w}];
        const auto seed = c.find(PlannerKind::Seed);
        const auto pred = c.find(PlannerKind::Predictive);
        const double s = seed == c.end() ? -1.0 : seed->second;
        const double p = pred == c.end() ? -1.0 : pred->second;
        if (s > 0.0 && p >= 0.0)
          std::snprintf(buf, sizeof buf, "            %5.3f %5.3f %5.2f |", s, p, p / s);
        else
          std::snprintf(buf, sizeof buf, "            %5.3f %5.3f   -   |", s, p);
        out << buf;
      }
      out << "\n";
    }
  }
  return out.str();
}

Image render_map(const FollowMap& map, const PlannerSettings& settings, const MapStyle& style) {
  const int px = std::max(1, style.pixels_per_cell);
  Image img;
  img.width = img.height = map.cells_per_side * px;
  img.rgb.assign(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * 3u, 255);
  const auto set = [&](int x, int y, std::uint8_t r, std::uint8_t gr, std::uint8_t b) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 3u;
    img.rgb[i] = r;
    img.rgb[i + 1] = gr;
    img.rgb[i + 2] = b;
  };
  // World (x, z) -> pixel: x to the right, z down.
  const double scale = px / map.cell_m;
  const auto to_px = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2i(static_cast<int>(std::floor((p.x() + map.half_size_m) * scale)),
                           static_cast<int>(std::floor((p.y() + map.half_size_m) * scale)));
  };
  for (int iz = 0; iz < map.cells_per_side; ++iz)
    for (int ix = 0; ix < map.cells_per_side; ++ix)
      if (map.followed[static_cast<std::size_t>(iz * map.cells_per_side + ix)])
        for (int y = 0; y < px; ++y)
          for (int x = 0; x < px; ++x) set(ix * px + x, iz * px + y, 60, 110, 220);
  const Eigen::Vector2i origin = to_px({0.0, 0.0});
  for (int i = 0; i < img.width; ++i) {
    if (i % 4 < 2) {
      set(i, origin.y(), 150, 150, 150);
      set(origin.x(), i, 150, 150, 150);
    }
  }
  // The user's cylinder (collision radius) and d' circle at the start.
  for (int a = 0; a < 720; ++a) {
    const Eigen::Vector2d dir = g::direction(a * std::numbers::pi / 360.0);
    const Eigen::Vector2i c = to_px(settings.collision_radius_m() * dir);
    set(c.x(), c.y(), 0, 0, 0);
  }
  const Eigen::Vector2i base = to_px({settings.target_distance_m(), 0.0});
  for (int y = -3; y <= 3; ++y)
    for (int x = -3; x <= 3; ++x) {
      set(base.x() + x, base.y() + y, 220, 30, 30);
      set(origin.x() + x / 2, origin.y() + y / 2, 0, 0, 0);
    }
  return img;
}

Image tile(const std::vector<Image>& images, int columns, int gap_px) {
  Image out;
  if (images.empty() || columns <= 0) return out;
  const int w = images.front().width;
  const int h = images.front().height;
  const int rows = (static_cast<int>(images.size()) + columns - 1) / columns;
  out.width = columns * w + (columns + 1) * gap_px;
  out.height = rows * h + (rows + 1) * gap_px;
  out.rgb.assign(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 3u, 255);
  for (std::size_t k = 0; k < images.size(); ++k) {
    const int col = static_cast<int>(k) % columns;
    const int row = static_cast<int>(k) / columns;
    const int x0 = gap_px + col * (w + gap_px);
    const int y0 = gap_px + row * (h + gap_px);
    const Image& im = images[k];
    for (int y = 0; y < std::min(h, im.height); ++y)
      std::copy_n(im.rgb.begin() + static_cast<std::ptrdiff_t>(y) * im.width * 3, std::min(w, im.width) * 3,
                  out.rgb.begin() + (static_cast<std::ptrdiff_t>(y0 + y) * out.width + x0) * 3);
  }
  return out;
}

std::string write_png(const std::filesystem::path& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0) return "empty image";
  std::FILE* file = std::fopen(path.string().c_str(), "wb");
  if (file == nullptr) return "cannot open '" + path.string() + "' for writing";
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (png == nullptr || info == nullptr) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return "libpng: out of memory";
  }
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y)
    rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(image.rgb.data()) +
                                        static_cast<std::ptrdiff_t>(y) * image.width * 3;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return "libpng: error writing '" + path.string() + "'";
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  const bool closed = std::fclose(file) == 0;
  return closed ? std::string() : "cannot close '" + path.string() + "'";
}

}  // namespace mhd::plan_sim
