#include "plan_sim_command.h"

#include "command_exit.h"
#include "plan_sim.h"
#include "shared_floor.h"
#include "planner/planner_settings.h"

#include <fmt/core.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <system_error>
#include <vector>

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct PlanSimOptions {
  std::string out = "plan_sim_out";
  std::string planner = "both";
  std::vector<double> v_mps{0.1, 0.2, 0.3, 0.4, 0.5};
  std::vector<double> omega_degps{45.0, 60.0, 75.0, 90.0};
  std::vector<double> facing_deg{0.0, 45.0, 90.0};
  double cell_mm = 25.0;
  double half_size_m = 1.5;
  std::vector<std::string> sets;
  bool no_maps = false;
  // The followed volume (3-D): hand heights, and the lift that the "with the lift" column uses.
  bool volume = false;
  double height_min_m = 0.3;
  double height_max_m = 1.9;
  double height_step_m = 0.1;
  std::vector<double> lift_range_m{-0.7, 0.9};
  double lift_speed_mps = 0.3;
  double lift_acceleration_mps2 = 1.5;
  // Several rigs on one floor.
  bool shared_floor = false;
  int rigs = 2;
  int sessions = 500;
  std::uint64_t first_seed = 1000000;
  double duration_s = 30.0;
  double tracking_delay_s = 0.05;
};

int fail(const std::string& message) {
  fmt::print(stderr, "mhd plan-sim: error: {}\n", message);
  return 1;
}

/// One planner and set of limits of the sweep: its settings (checked) and its map's spec.
struct SweepCase {
  mhd::PlannerKind kind{};
  double facing_deg = 0.0, v_mps = 0.0, omega_degps = 0.0;
  mhd::PlannerSettings settings;
  mhd::plan_sim::MapSpec spec;
};

/// Every case, planner by planner, then by facing change, linear and angular speed;
/// `invalid` receives the first setting the planner refuses (and no cases are returned).
std::vector<SweepCase> sweep_cases(const PlanSimOptions& o, const mhd::PlannerSettings& parsed,
                                   const std::vector<mhd::PlannerKind>& kinds, std::string& invalid) {
  std::vector<SweepCase> cases;
  for (const mhd::PlannerKind kind : kinds) {
    for (const double facing : o.facing_deg) {
      for (const double v : o.v_mps) {
        for (const double w : o.omega_degps) {
          SweepCase c{kind, facing, v, w, parsed, {}};
          c.settings.max_linear_speed_mps = v;
          c.settings.max_angular_speed_radps = w * kDeg;
          if (const auto errors = mhd::validate(c.settings); !errors.empty()) {
            invalid = errors.front();
            return {};
          }
          c.spec.cell_m = o.cell_mm * 1e-3;
          c.spec.half_size_m = o.half_size_m;
          c.spec.facing_change_rad = facing * kDeg;
          cases.push_back(c);
        }
      }
    }
  }
  return cases;
}

/// The followed volume, without and with the lift, for each planner and limit: a table on
/// stdout and plan_sim_volumes.csv.
int run_volume(const PlanSimOptions& o, const mhd::PlannerSettings& parsed, const std::vector<mhd::PlannerKind>& kinds) {
  if (!(o.height_step_m > 0.0) || !(o.height_min_m > 0.0) || !(o.height_max_m > o.height_min_m)) {
    return fail("--heights-m must be MIN MAX STEP with 0 < MIN < MAX and STEP > 0");
  }
  if (o.lift_range_m.size() != 2 || !(o.lift_range_m[0] <= 0.0) || !(o.lift_range_m[1] >= 0.0) ||
      !(o.lift_range_m[0] < o.lift_range_m[1]) || !(o.lift_speed_mps > 0.0) || !(o.lift_acceleration_mps2 > 0.0)) {
    return fail("the lift needs --lift-range-m MIN MAX with MIN <= 0 <= MAX, MIN < MAX, and positive limits");
  }
  std::vector<double> heights;
  for (int i = 0; o.height_min_m + i * o.height_step_m <= o.height_max_m + 1e-9; ++i) {
    heights.push_back(o.height_min_m + i * o.height_step_m);
  }
  if (heights.size() < 2) return fail("--heights-m gives fewer than two heights");
  const mhd::Lift lift{o.lift_range_m[0], o.lift_range_m[1], o.lift_speed_mps, o.lift_acceleration_mps2};
  std::string csv_text =
      "planner,facing_change_deg,max_linear_speed_mps,max_angular_speed_degps,volume_without_lift_m3,"
      "volume_with_lift_m3,base_entries\n";
  fmt::print("followed volume (m^3), hand at {:g}..{:g} m every {:g} m; lift {:g}..{:g} m, {:g} m/s, {:g} m/s^2\n",
             o.height_min_m, heights.back(), o.height_step_m, lift.min_m, lift.max_m, lift.max_speed_mps,
             lift.max_acceleration_mps2);
  fmt::print("{:<11} {:>7} {:>6} {:>8} {:>14} {:>11}\n", "planner", "facing", "v m/s", "w deg/s", "without lift",
             "with lift");
  std::string invalid;
  std::vector<SweepCase> cases = sweep_cases(o, parsed, kinds, invalid);
  if (!invalid.empty()) return fail(invalid);
  for (SweepCase& c : cases) {
    c.spec.vertical = mhd::plan_sim::VerticalReach{};
    const auto fixed = mhd::plan_sim::simulate_volume(c.kind, c.settings, c.spec, heights);
    c.spec.vertical->lift = lift;
    const auto lifted = mhd::plan_sim::simulate_volume(c.kind, c.settings, c.spec, heights);
    fmt::print("{:<11} {:>7.0f} {:>6.2f} {:>8.0f} {:>14.3f} {:>11.3f}\n", mhd::to_string(c.kind), c.facing_deg, c.v_mps,
               c.omega_degps, fixed.followed_volume_m3(), lifted.followed_volume_m3());
    csv_text += fmt::format("{},{:.0f},{:.2f},{:.0f},{:.4f},{:.4f},{}\n", mhd::to_string(c.kind), c.facing_deg, c.v_mps,
                            c.omega_degps, fixed.followed_volume_m3(), lifted.followed_volume_m3(),
                            fixed.base_entries + lifted.base_entries);
  }
  const std::filesystem::path csv = std::filesystem::path(o.out) / "plan_sim_volumes.csv";
  std::ofstream out(csv);
  out << csv_text;
  if (!out) return fail("cannot write '" + csv.string() + "'");
  fmt::print("wrote {}\n", csv.string());
  return 0;
}

/// Sessions of several rigs on one floor, each planner seeing the others and, for
/// comparison, blind to them: a table on stdout and plan_sim_shared_floor.csv. Exit 3 when
/// a rig that sees the others enters a keep-out.
int run_shared_floor(const PlanSimOptions& o, const mhd::PlannerSettings& settings,
                     const std::vector<mhd::PlannerKind>& kinds) {
  const int most = static_cast<int>(mhd::KeepOuts::kCapacity / 2) + 1;
  if (o.rigs < 1 || o.rigs > most) return fail(fmt::format("--rigs must be 1..{}", most));
  if (o.sessions < 1) return fail("--sessions must be >= 1");
  if (!(o.duration_s > 0.0) || !(o.duration_s <= 3600.0)) return fail("--duration-s must be > 0 and <= 3600");
  if (!(o.tracking_delay_s >= 0.0) || !(o.tracking_delay_s <= 1.0))
    return fail("--tracking-delay-s must be >= 0 and <= 1");
  std::string csv_text =
      "planner,sees_others,rigs,sessions,first_seed,ticks,base_user_intrusions,base_base_intrusions,"
      "min_base_user_m,min_base_other_user_m,min_base_base_m,user_walked_into_base_ticks,followed_fraction\n";
  fmt::print("{} rigs on one floor, {} sessions of {:g} s from seed {}, the others tracked {:g} s late\n", o.rigs,
             o.sessions, o.duration_s, o.first_seed, o.tracking_delay_s);
  fmt::print("{:<11} {:<6} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>9}\n", "planner", "sees", "base-user",
             "base-base", "min b-u", "min b-ou", "min b-b", "walked in", "followed");
  std::int64_t intrusions = 0;
  for (const mhd::PlannerKind kind : kinds) {
    for (const bool sees : {true, false}) {
      mhd::plan_sim::SharedFloorSpec spec;
      spec.kind = kind;
      spec.rigs = o.rigs;
      spec.duration_s = o.duration_s;
      spec.tracking_delay_s = o.tracking_delay_s;
      spec.see_others = sees;
      const auto f = mhd::plan_sim::simulate_shared_floors(settings, spec, o.first_seed, o.sessions);
      const double followed = static_cast<double>(f.followed_ticks) / static_cast<double>(f.ticks);
      if (sees) intrusions += f.base_user_intrusions + f.base_base_intrusions;
      fmt::print("{:<11} {:<6} {:>10} {:>10} {:>10.3f} {:>10.3f} {:>10.3f} {:>10} {:>8.1f}%\n", mhd::to_string(kind),
                 sees ? "yes" : "no", f.base_user_intrusions, f.base_base_intrusions, f.min_base_user_m,
                 f.min_base_other_user_m, f.min_base_base_m, f.user_walked_into_base_ticks, 100.0 * followed);
      csv_text += fmt::format("{},{},{},{},{},{},{},{},{:.4f},{:.4f},{:.4f},{},{:.4f}\n", mhd::to_string(kind),
                              sees ? 1 : 0, o.rigs, o.sessions, o.first_seed, f.ticks, f.base_user_intrusions,
                              f.base_base_intrusions, f.min_base_user_m, f.min_base_other_user_m, f.min_base_base_m,
                              f.user_walked_into_base_ticks, followed);
    }
  }
  fmt::print("base-user, base-base: sub-steps a base entered a user's or another base's contact distance by its "
             "own motion; min: least distances between centres (m; b-ou: other rigs' users); walked in: ticks a "
             "user walked into a base; followed: ticks with the hand in the usable workspace\n");
  const std::filesystem::path csv = std::filesystem::path(o.out) / "plan_sim_shared_floor.csv";
  std::ofstream out(csv);
  out << csv_text;
  if (!out) return fail("cannot write '" + csv.string() + "'");
  fmt::print("wrote {}\n", csv.string());
  return intrusions == 0 ? 0 : 3;
}

int run(const PlanSimOptions& o) {
  std::map<std::string, std::string> values;
  for (const std::string& s : o.sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) return fail("--set expects NAME=VALUE, got '" + s + "'");
    values[s.substr(0, eq)] = s.substr(eq + 1);
  }
  const auto parsed = mhd::planner_settings_from_map(values);
  if (!parsed.ok()) {
    for (const std::string& e : parsed.error()) fmt::print(stderr, "mhd plan-sim: error: {}\n", e);
    return 1;
  }
  std::vector<mhd::PlannerKind> kinds;
  if (o.planner == "both") {
    kinds = {mhd::PlannerKind::Seed, mhd::PlannerKind::Predictive};
  } else {
    mhd::PlannerKind kind{};
    if (!mhd::parse_planner_kind(o.planner, kind))
      return fail("--planner must be seed, predictive or both, got '" + o.planner + "'");
    kinds = {kind};
  }
  if (!(o.cell_mm > 0.0) || !(o.half_size_m > 0.0)) return fail("--cell-mm and --half-size-m must be > 0");
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) return fail("cannot create '" + o.out + "': " + ec.message());
  if (o.volume) return run_volume(o, *parsed, kinds);
  if (o.shared_floor) return run_shared_floor(o, *parsed, kinds);
  const std::filesystem::path maps_dir = std::filesystem::path(o.out) / "maps";
  if (!o.no_maps) {
    std::filesystem::create_directories(maps_dir, ec);
    if (ec) return fail("cannot create '" + maps_dir.string() + "': " + ec.message());
  }

  std::vector<mhd::plan_sim::TableRow> rows;
  double simulated_s = 0.0;
  const auto start = std::chrono::steady_clock::now();
  std::string invalid;
  const std::vector<SweepCase> cases = sweep_cases(o, *parsed, kinds, invalid);
  if (!invalid.empty()) return fail(invalid);
  for (const SweepCase& c : cases) {
    const mhd::plan_sim::FollowMap map = mhd::plan_sim::simulate_map(c.kind, c.settings, c.spec);
    simulated_s += c.spec.horizon_s * map.cells_per_side * map.cells_per_side;
    rows.push_back({c.kind, c.spec.facing_change_rad, c.v_mps, c.omega_degps * kDeg, map.followed_area_m2(),
                    map.followed_cells, map.base_entries});
    if (o.no_maps) continue;
    const std::filesystem::path file = maps_dir / fmt::format("planner_{}_f{:.0f}_v{:.1f}_w{:.0f}.csv",
                                                              mhd::to_string(c.kind), c.facing_deg, c.v_mps,
                                                              c.omega_degps);
    std::ofstream map_out(file);
    map_out << mhd::plan_sim::map_csv(map, c.kind, c.settings, c.spec);
    if (!map_out) return fail("cannot write '" + file.string() + "'");
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::filesystem::path csv = std::filesystem::path(o.out) / "plan_sim_areas.csv";
  std::ofstream out(csv);
  out << mhd::plan_sim::table_csv(rows);
  if (!out) return fail("cannot write '" + csv.string() + "'");
  fmt::print("{}", mhd::plan_sim::table_text(rows));
  int entries = 0;
  for (const auto& r : rows) entries += r.base_entries;
  fmt::print("simulated {:.0f} s of planner time in {:.2f} s ({:.0f}x real time); base moved into the user: {}\n",
             simulated_s, wall_s, simulated_s / wall_s, entries);
  fmt::print("wrote {}{}\n", csv.string(), o.no_maps ? "" : " and the follow maps in " + maps_dir.string());
  // The pictures need a plotting library: matplotlib draws them from the CSVs.
  if (!o.no_maps) fmt::print("draw them: /usr/bin/python3 tools/plots/plan_sim_maps.py {}\n", o.out);
  return 0;
}

}  // namespace

void add_plan_sim_command(CLI::App& app) {
  auto o = std::make_shared<PlanSimOptions>();
  CLI::App* cmd = app.add_subcommand(
      "plan-sim", "Planner simulator (thesis ch. 3.6): maps of user moves the base follows within 1 s");
  cmd->add_option("--out", o->out, "Output folder for the area table and the follow maps (CSV)")->capture_default_str();
  cmd->add_option("--planner", o->planner, "seed, predictive or both")->capture_default_str();
  cmd->add_option("--v-mps", o->v_mps, "Maximum linear speeds")->capture_default_str();
  cmd->add_option("--omega-degps", o->omega_degps, "Maximum angular speeds")->capture_default_str();
  cmd->add_option("--facing-deg", o->facing_deg, "Changes of the user's facing")->capture_default_str();
  cmd->add_option("--cell-mm", o->cell_mm, "Grid cell size")->capture_default_str();
  cmd->add_option("--half-size-m", o->half_size_m, "The grid covers +-this around the user's start")
      ->capture_default_str();
  cmd->add_option("--set", o->sets, "Planner setting NAME=VALUE (e.g. step_angle_deg=30)")->type_name("NAME=VALUE");
  cmd->add_flag("--no-maps", o->no_maps, "Only the area table, no follow-map CSVs");
  cmd->add_flag("--volume", o->volume,
                "The followed volume instead of the area: the hand at several heights, the arm fixed or on a lift");
  cmd->add_option_function<std::vector<double>>(
         "--heights-m",
         [o](const std::vector<double>& h) {
           if (h.size() != 3) throw CLI::ValidationError("--heights-m", "expects MIN MAX STEP");
           o->height_min_m = h[0];
           o->height_max_m = h[1];
           o->height_step_m = h[2];
         },
         "With --volume: the hand's heights, MIN MAX STEP (default 0.3 1.9 0.1)")
      ->expected(3);
  cmd->add_option("--lift-range-m", o->lift_range_m, "With --volume: the lift's range, MIN MAX")
      ->expected(2)
      ->capture_default_str();
  cmd->add_option("--lift-speed-mps", o->lift_speed_mps, "With --volume: the lift's speed limit")->capture_default_str();
  cmd->add_option("--lift-acceleration-mps2", o->lift_acceleration_mps2, "With --volume: its acceleration limit")
      ->capture_default_str();
  cmd->add_flag("--shared-floor", o->shared_floor,
                "Several rigs on one floor: random users, each base keeping out of the others' way (exit 3 on an "
                "intrusion)");
  cmd->add_option("--rigs", o->rigs, "With --shared-floor: rigs (and users) on the floor")->capture_default_str();
  cmd->add_option("--sessions", o->sessions, "With --shared-floor: sessions")->capture_default_str();
  cmd->add_option("--first-seed", o->first_seed, "With --shared-floor: the first session's seed")
      ->capture_default_str();
  cmd->add_option("--duration-s", o->duration_s, "With --shared-floor: each session's length")->capture_default_str();
  cmd->add_option("--tracking-delay-s", o->tracking_delay_s,
                  "With --shared-floor: the age of the others' poses when a rig plans")
      ->capture_default_str();
  cmd->callback([o] { mhd::cli::exit_with(run(*o)); });
}
