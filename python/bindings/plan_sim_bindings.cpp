// The planner simulator of thesis ch. 3.6 from Python (tools/plan_sim, behind `mhd
// plan-sim`): single cases over an array of next user positions, and whole follow maps.
// Planner settings come as a dict of the names `mhd plan-sim --set` takes (with their unit
// suffix); a bad name or value is a ValueError with the planner's own message.

#include "bindings.h"

#include "plan_sim.h"
#include "planner/planner_settings.h"

#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <string>

namespace py = pybind11;

namespace mhd::python {
namespace {

PlannerKind planner_kind(const std::string& name) {
  PlannerKind kind{};
  if (!parse_planner_kind(name, kind)) throw py::value_error("planner must be 'seed' or 'predictive', got '" + name + "'");
  return kind;
}

/// {name: value} (value a number or its text) over the defaults, validated.
PlannerSettings planner_settings(const py::dict& values) {
  std::map<std::string, std::string> text;
  for (const auto& [name, value] : values) {
    text[py::cast<std::string>(py::str(name))] = py::cast<std::string>(py::str(value));
  }
  const Result<PlannerSettings, std::vector<std::string>> parsed = planner_settings_from_map(text);
  if (!parsed.ok()) throw py::value_error(parsed.error_text());
  return *parsed;
}

plan_sim::MapSpec map_spec(double facing_change_rad, double horizon_s, int substeps) {
  if (!std::isfinite(facing_change_rad)) throw py::value_error("facing_change_rad must be finite");
  if (!(std::isfinite(horizon_s) && horizon_s > 0.0)) throw py::value_error("horizon_s must be finite and > 0");
  if (substeps < 1) throw py::value_error("substeps must be >= 1");
  plan_sim::MapSpec spec;
  spec.facing_change_rad = facing_change_rad;
  spec.horizon_s = horizon_s;
  spec.substeps = substeps;
  return spec;
}

py::dict simulate_cases(const py::array_t<double, py::array::c_style | py::array::forcecast>& next_user_W_m,
                        const std::string& planner, const py::dict& settings, double facing_change_rad,
                        double horizon_s, int substeps) {
  if (next_user_W_m.ndim() != 2 || next_user_W_m.shape(1) != 2) {
    throw py::value_error("next_user_W_m must have shape (N, 2): world x and z of each next user position, m");
  }
  const PlannerKind kind = planner_kind(planner);
  const PlannerSettings s = planner_settings(settings);
  const plan_sim::MapSpec spec = map_spec(facing_change_rad, horizon_s, substeps);
  const py::ssize_t n = next_user_W_m.shape(0);
  py::array_t<bool> followed(n);
  py::array_t<double> time_s(n);
  py::array_t<bool> base_entered(n);
  const double* user = next_user_W_m.data();
  for (py::ssize_t k = 0; k < n; ++k) {
    if (!(std::isfinite(user[2 * k]) && std::isfinite(user[2 * k + 1]))) {
      throw py::value_error(fmt::format("next_user_W_m[{}] = ({}, {}) is not finite", k, user[2 * k], user[2 * k + 1]));
    }
  }
  bool* f = followed.mutable_data();
  double* t = time_s.mutable_data();
  bool* e = base_entered.mutable_data();
  {
    py::gil_scoped_release unlocked;
    for (py::ssize_t k = 0; k < n; ++k) {
      const plan_sim::CaseFigures r = plan_sim::simulate_case(kind, s, spec, Eigen::Vector2d(user[2 * k], user[2 * k + 1]));
      f[k] = r.followed;
      t[k] = r.followed ? r.time_s : std::nan("");
      e[k] = r.base_entered;
    }
  }
  py::dict result;
  result["followed"] = followed;
  result["time_s"] = time_s;
  result["base_entered"] = base_entered;
  return result;
}

py::dict simulate_map(const std::string& planner, const py::dict& settings, double half_size_m, double cell_m,
                      double facing_change_rad, double horizon_s, int substeps) {
  if (!(std::isfinite(half_size_m) && half_size_m > 0.0 && std::isfinite(cell_m) && cell_m > 0.0)) {
    throw py::value_error("half_size_m and cell_m must be finite and > 0");
  }
  if (2.0 * half_size_m / cell_m > 4000.0) throw py::value_error("at most 4000 cells per side");
  const PlannerKind kind = planner_kind(planner);
  const PlannerSettings s = planner_settings(settings);
  plan_sim::MapSpec spec = map_spec(facing_change_rad, horizon_s, substeps);
  spec.half_size_m = half_size_m;
  spec.cell_m = cell_m;
  plan_sim::FollowMap map;
  {
    py::gil_scoped_release unlocked;
    map = plan_sim::simulate_map(kind, s, spec);
  }
  const py::ssize_t side = map.cells_per_side;
  py::array_t<bool> followed({side, side});
  py::array_t<double> follow_time_s({side, side});
  py::array_t<double> centres_m(side);
  for (py::ssize_t i = 0; i < side * side; ++i) {
    const bool cell_followed = map.followed[static_cast<std::size_t>(i)] != 0;
    followed.mutable_data()[i] = cell_followed;
    follow_time_s.mutable_data()[i] = cell_followed ? map.follow_time_s[static_cast<std::size_t>(i)] : std::nan("");
  }
  for (int i = 0; i < map.cells_per_side; ++i) centres_m.mutable_data()[i] = map.cell_center(i, 0).x();
  py::dict result;
  result["followed"] = followed;
  result["follow_time_s"] = follow_time_s;
  result["x_m"] = centres_m;
  result["z_m"] = centres_m;  // the grid is square and centred on the user's start
  result["followed_cells"] = map.followed_cells;
  result["followed_area_m2"] = map.followed_area_m2();
  result["base_entries"] = map.base_entries;
  result["map_csv"] = plan_sim::map_csv(map, kind, s, spec);
  return result;
}

}  // namespace

void bind_plan_sim(py::module_& m) {
  m.def("plan_sim_cases", &simulate_cases, py::arg("next_user_W_m"), py::arg("planner") = "seed",
        py::arg("settings") = py::dict(), py::arg("facing_change_rad") = 0.0, py::arg("horizon_s") = 1.0,
        py::arg("substeps") = 10,
        "Thesis ch. 3.6 cases: the user steps from the origin to each row (world x, z in m) and turns by "
        "facing_change_rad; does the base bring the hand back into the usable workspace within horizon_s? "
        "Returns {'followed': (N,) bool, 'time_s': (N,) when (nan if not), 'base_entered': (N,) bool}.");
  m.def("plan_sim_map", &simulate_map, py::arg("planner") = "seed", py::arg("settings") = py::dict(),
        py::arg("half_size_m") = 1.5, py::arg("cell_m") = 0.025, py::arg("facing_change_rad") = 0.0,
        py::arg("horizon_s") = 1.0, py::arg("substeps") = 10,
        "A follow map (thesis Fig. 3.8-3.10): every cell of a square grid around the user's start. Returns "
        "{'followed': (n, n) bool [z index, x index], 'follow_time_s': (n, n) (nan where not followed), "
        "'x_m', 'z_m': (n,) cell centres, 'followed_cells', 'followed_area_m2', 'base_entries', "
        "'map_csv': the map as `mhd plan-sim` writes it}.");
}

}  // namespace mhd::python
