#include "plan_sim.h"

#include "planner/lift_planner.h"
#include "planner/planner_geometry.h"

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

Eigen::Vector3d hand_of(const Eigen::Vector2d& user, double heading, double reach, double height_m) {
  const Eigen::Vector2d h = user + reach * g::direction(heading);
  return Eigen::Vector3d(h.x(), height_m, h.y());
}

/// The arm's height over one case: fixed, or on a lift that LiftPlanner drives from 0
/// towards the hand. inside(t) says whether the hand is within the reach at time t (called
/// with increasing t).
class VerticalTrack {
 public:
  VerticalTrack(const std::optional<VerticalReach>& reach, double hand_height_m)
      : reach_(reach), hand_height_m_(hand_height_m) {
    if (reach_ && reach_->lift) {
      planner_.emplace(*reach_->lift, 0.5 * (reach_->low_m + reach_->high_m));
      target_m_ = planner_->target_for_hand(hand_height_m, 0.0);
    }
  }

  [[nodiscard]] bool inside(double t_s) {
    if (!reach_) return true;
    if (planner_) {
      constexpr double kStep_s = 1e-3;
      for (; lift_t_s_ + kStep_s <= t_s + 1e-12; lift_t_s_ += kStep_s) lift_ = planner_->step(lift_, target_m_, kStep_s);
    }
    return hand_height_m_ >= reach_->low_m + lift_.height_m && hand_height_m_ <= reach_->high_m + lift_.height_m;
  }

 private:
  std::optional<VerticalReach> reach_;
  double hand_height_m_;
  std::optional<LiftPlanner> planner_;
  double target_m_ = 0.0;
  LiftState lift_;
  double lift_t_s_ = 0.0;
};

}  // namespace

CaseFigures simulate_case(PlannerKind kind, const PlannerSettings& settings, const MapSpec& spec,
                         const Eigen::Vector2d& next_user_W) {
  const std::unique_ptr<Planner> planner = make_planner(kind, settings);
  const double reach = settings.arm_length_m;
  const Eigen::Vector2d start_user(0.0, 0.0);
  const Eigen::Vector2d start_base = g::follow_target(start_user, {reach, 0.0}, 0.0, settings.target_distance_m());
  BasePose base{start_base.x(), start_base.y(), g::facing_heading(start_base, start_user, settings.facing_angle_rad)};

  const double heading = spec.facing_change_rad;
  const Eigen::Vector3d hip = hand_of(next_user_W, heading, reach, spec.hand_height_m);
  const double r_collision = settings.collision_radius_m();
  VerticalTrack vertical(spec.vertical, spec.hand_height_m);
  const auto hip_inside = [&](const BasePose& b, double t_s) {
    const Eigen::Vector2d p = g::hip_in_base(b, hip);
    return settings.usable_B.contains(p.x(), p.y()) && vertical.inside(t_s);
  };

  CaseFigures result;
  if (hip_inside(base, 0.0)) {
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
      if (!result.followed && hip_inside(b, in.time_s + dt)) {
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
  const std::size_t cells = static_cast<std::size_t>(map.cells_per_side) * static_cast<std::size_t>(map.cells_per_side);
  map.followed.assign(cells, 0);
  map.follow_time_s.assign(cells, 0.0);
  for (int iz = 0; iz < map.cells_per_side; ++iz) {
    for (int ix = 0; ix < map.cells_per_side; ++ix) {
      const CaseFigures r = simulate_case(kind, settings, spec, map.cell_center(ix, iz));
      if (r.followed) {
        map.followed[static_cast<std::size_t>(iz * map.cells_per_side + ix)] = 1;
        map.follow_time_s[static_cast<std::size_t>(iz * map.cells_per_side + ix)] = r.time_s;
        ++map.followed_cells;
      }
      if (r.base_entered) ++map.base_entries;
    }
  }
  return map;
}

double FollowVolume::followed_volume_m3() const noexcept {
  double cells = 0.0;
  for (const int n : followed_cells) cells += n;
  return cells * cell_m * cell_m * height_step_m;
}

FollowVolume simulate_volume(PlannerKind kind, const PlannerSettings& settings, MapSpec spec,
                             const std::vector<double>& hand_heights_m) {
  FollowVolume volume;
  volume.hand_heights_m = hand_heights_m;
  volume.cell_m = spec.cell_m;
  volume.height_step_m = hand_heights_m.size() >= 2 ? hand_heights_m[1] - hand_heights_m[0] : 0.0;
  if (!spec.vertical) spec.vertical = VerticalReach{};
  for (const double height_m : hand_heights_m) {
    spec.hand_height_m = height_m;
    const FollowMap map = simulate_map(kind, settings, spec);
    volume.followed_cells.push_back(map.followed_cells);
    volume.base_entries += map.base_entries;
  }
  return volume;
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

std::string map_csv(const FollowMap& map, PlannerKind kind, const PlannerSettings& settings, const MapSpec& spec) {
  const Eigen::Vector2d user_W(0.0, 0.0);
  const Eigen::Vector2d base_W =
      g::follow_target(user_W, {settings.arm_length_m, 0.0}, 0.0, settings.target_distance_m());
  const double base_heading_rad = g::facing_heading(base_W, user_W, settings.facing_angle_rad);
  std::ostringstream out;
  char line[160];
  const auto meta = [&](const char* name, double value) {
    std::snprintf(line, sizeof line, "# %s=%.6g\n", name, value);
    out << line;
  };
  out << "# mhd plan-sim follow map (thesis ch. 3.6); draw with tools/plots/plan_sim_maps.py\n";
  out << "# planner=" << to_string(kind) << "\n";
  meta("max_linear_speed_mps", settings.max_linear_speed_mps);
  meta("max_angular_speed_degps", settings.max_angular_speed_radps / kDeg);
  meta("facing_change_deg", spec.facing_change_rad / kDeg);
  meta("horizon_s", spec.horizon_s);
  meta("half_size_m", map.half_size_m);
  meta("cell_m", map.cell_m);
  meta("user_start_x_m", user_W.x());
  meta("user_start_z_m", user_W.y());
  meta("user_start_heading_deg", 0.0);
  meta("arm_length_m", settings.arm_length_m);
  meta("collision_radius_m", settings.collision_radius_m());
  meta("base_start_x_m", base_W.x());
  meta("base_start_z_m", base_W.y());
  meta("base_start_heading_deg", base_heading_rad / kDeg);
  meta("followed_cells", map.followed_cells);
  meta("followed_area_m2", map.followed_area_m2());
  meta("base_entries", map.base_entries);
  out << "x_m,z_m,follow_time_s\n";
  for (int iz = 0; iz < map.cells_per_side; ++iz) {
    for (int ix = 0; ix < map.cells_per_side; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iz * map.cells_per_side + ix);
      if (!map.followed[i]) continue;
      const Eigen::Vector2d c = map.cell_center(ix, iz);
      std::snprintf(line, sizeof line, "%.4f,%.4f,%.3f\n", c.x(), c.y(), map.follow_time_s[i]);
      out << line;
    }
  }
  return out.str();
}

}  // namespace mhd::plan_sim
