"""The planner simulator (thesis ch. 3.6) from Python: maps and single cases agree with each
other and with `mhd plan-sim`; settings take `--set`'s names and fail with its messages."""

import math

import numpy as np
import pytest

import mhd
from conftest import run_cli

COARSE = dict(half_size_m=1.5, cell_m=0.1)  # 30 x 30 cells: quick


def test_the_map_counts_what_mhd_plan_sim_counts(tmp_path):
    settings = {"max_linear_speed_mps": 0.3, "max_angular_speed_degps": 60}
    for planner in ("seed", "predictive"):
        for facing_deg in (0, 90):
            m = mhd.plan_sim_map(planner, settings, facing_change_rad=math.radians(facing_deg), **COARSE)
            cli = run_cli("plan-sim", "--out", str(tmp_path / "plan_sim"), "--planner", planner, "--cell-mm", "100",
                          "--v-mps", "0.3", "--omega-degps", "60", "--facing-deg", str(facing_deg), "--no-maps")
            assert cli.returncode == 0, cli.stderr
            table = np.genfromtxt(tmp_path / "plan_sim" / "plan_sim_areas.csv", delimiter=",", names=True,
                                  dtype=None, encoding="utf-8")
            assert m["followed_cells"] == int(table["followed_cells"])
            assert m["base_entries"] == int(table["base_entries"])
            assert m["followed_area_m2"] == pytest.approx(float(table["followed_area_m2"]), abs=1e-4)
            assert m["followed"].sum() == m["followed_cells"]


def test_cases_at_the_cell_centres_give_the_map():
    m = mhd.plan_sim_map("predictive", facing_change_rad=math.radians(45), **COARSE)
    x, z = np.meshgrid(m["x_m"], m["z_m"])  # rows: z, columns: x, as the map
    cases = mhd.plan_sim_cases(np.column_stack([x.ravel(), z.ravel()]), "predictive",
                               facing_change_rad=math.radians(45))
    np.testing.assert_array_equal(cases["followed"].reshape(m["followed"].shape), m["followed"])
    np.testing.assert_array_equal(cases["time_s"].reshape(m["followed"].shape), m["follow_time_s"])


def test_near_is_followed_at_once_far_is_not():
    cases = mhd.plan_sim_cases([[0.0, 0.0], [1.45, 1.45]], "seed")
    assert cases["followed"].tolist() == [True, False]
    assert cases["time_s"][0] == 0.0 and math.isnan(cases["time_s"][1])
    assert cases["base_entered"].dtype == np.bool_


def test_a_faster_base_follows_more():
    slow = mhd.plan_sim_map("seed", {"max_linear_speed_mps": 0.1}, **COARSE)
    fast = mhd.plan_sim_map("seed", {"max_linear_speed_mps": 0.5}, **COARSE)
    assert fast["followed_area_m2"] > slow["followed_area_m2"]


def test_bad_settings_are_value_errors_with_the_planners_message():
    with pytest.raises(ValueError, match=r"unknown planner setting 'max_speed' \(known: arm_length_m\|mm"):
        mhd.plan_sim_cases([[0.0, 0.0]], settings={"max_speed": 1})
    with pytest.raises(ValueError, match=r"planner setting 'stop_interval_m': 'abc' is not a number"):
        mhd.plan_sim_map(settings={"stop_interval_m": "abc"})
    with pytest.raises(ValueError, match=r"planner must be 'seed' or 'predictive', got 'thesis'"):
        mhd.plan_sim_map("thesis")
    with pytest.raises(ValueError, match=r"shape \(N, 2\)"):
        mhd.plan_sim_cases([0.0, 0.0])
    with pytest.raises(ValueError, match=r"next_user_W_m\[1\] = \(0\.5, nan\) is not finite"):
        mhd.plan_sim_cases([[0.0, 0.0], [0.5, float("nan")]])
