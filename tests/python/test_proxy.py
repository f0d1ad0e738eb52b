"""The god-object proxy stepped over NumPy arrays: the very numbers `mhd proxy-replay`
writes for the same path, the proxy never through the wall, state kept between calls,
and the GIL free while it steps."""

import re
import threading

import numpy as np
import pytest

import mhd
from conftest import push_path, repo_path, run_cli

WALL_Z_M = -0.3  # scenes/cube_wall.xml: the cube's front face


def test_replay_matches_mhd_proxy_replay_exactly(cube_wall, tmp_path):
    t_s, hip = push_path()
    hip_csv, ticks_csv = tmp_path / "hip.csv", tmp_path / "ticks.csv"
    np.savetxt(hip_csv, np.column_stack([t_s, hip]), delimiter=",", fmt="%.17g", header="t_s,x_m,y_m,z_m",
               comments="")
    cli = run_cli("proxy-replay", repo_path("scenes", "cube_wall.xml"), "--hip-csv", str(hip_csv),
                  "--out", str(ticks_csv))
    assert cli.returncode == 0, cli.stderr
    ticks = np.genfromtxt(ticks_csv, delimiter=",", names=True)

    trace = mhd.replay_proxy(cube_wall, t_s, hip)
    assert len(trace) == len(t_s)
    for i, a in enumerate("xyz"):
        np.testing.assert_array_equal(trace.proxy_W_m[:, i], ticks[f"proxy_{a}_m"])
        np.testing.assert_array_equal(trace.force_W_N[:, i], ticks[f"force_{a}_N"])
    np.testing.assert_array_equal(trace.contact, ticks["contact"] == 1)
    np.testing.assert_array_equal(trace.planes, ticks["planes"])
    np.testing.assert_array_equal(trace.budget_exhausted, ticks["budget_exhausted"] == 1)


def test_the_proxy_stays_on_the_wall_and_pushes_back(cube_wall):
    t_s, hip = push_path()
    trace = mhd.replay_proxy(cube_wall, t_s, hip)
    assert trace.proxy_W_m.dtype == np.float64 and trace.proxy_W_m.shape == (len(t_s), 3)
    assert trace.contact.dtype == np.bool_ and trace.planes.dtype == np.int32
    inside = hip[:, 2] < WALL_Z_M - 1e-4
    assert inside.any()
    assert np.all(trace.proxy_W_m[:, 2] >= WALL_Z_M)  # never through the surface
    assert np.all(trace.contact[inside])
    assert np.all(trace.contact_object[inside] == cube_wall.object_names.index("cube"))
    # Pushed back out of the wall (+z), never pulled in (damping can only cut the push to 0).
    assert np.all(trace.force_W_N[inside, 2] >= 0) and trace.force_W_N[inside, 2].max() > 5.0
    deep = hip[:, 2] < WALL_Z_M - 0.005
    assert np.all(trace.force_W_N[deep, 2] > 0)
    free = hip[:, 2] > WALL_Z_M + 1e-3
    np.testing.assert_array_equal(trace.proxy_W_m[free], hip[free])  # free space: on the hand
    np.testing.assert_array_equal(trace.force_W_N[free], 0.0)
    assert np.linalg.norm(trace.force_W_N, axis=1).max() <= cube_wall.max_force_N


def test_a_proxy_keeps_its_state_between_calls(cube_wall):
    t_s, hip = push_path()
    whole = mhd.Proxy(cube_wall, hip[0]).step(hip, 1e-3)
    proxy = mhd.Proxy(cube_wall, hip[0])
    first, second = proxy.step(hip[:150], 1e-3), proxy.step(hip[150:], np.full(250, 1e-3))
    np.testing.assert_array_equal(np.concatenate([first.force_W_N, second.force_W_N]), whole.force_W_N)
    np.testing.assert_array_equal(proxy.proxy_W_m, whole.proxy_W_m[-1])
    proxy.reset(hip[0])
    np.testing.assert_array_equal(proxy.proxy_W_m, hip[0])


def test_bad_input_is_a_value_error(cube_wall):
    t_s, hip = push_path(10)
    with pytest.raises(ValueError, match=r"is inside an object in .*cube_wall\.xml; the proxy must start in free"):
        mhd.Proxy(cube_wall, [0.0, 1.0, -0.5])
    proxy = mhd.Proxy(cube_wall, hip[0])
    with pytest.raises(ValueError, match=r"shape \(N, 3\)"):
        proxy.step(hip[:, :2])
    with pytest.raises(ValueError, match=r"dt_s\[3\] = 0 must be finite and > 0"):
        proxy.step(hip, np.where(np.arange(10) == 3, 0.0, 1e-3))
    with pytest.raises(ValueError, match=r"t_s must increase: t_s\[2\]"):
        mhd.replay_proxy(cube_wall, [0.0, 0.001, 0.001], hip[:3])


def test_a_non_finite_hip_is_refused_naming_its_row_and_nothing_is_stepped(cube_wall):
    t_s, hip = push_path(40)
    proxy = mhd.Proxy(cube_wall, hip[0])
    before = proxy.proxy_W_m.copy()
    for bad in (np.nan, np.inf, -np.inf):
        broken = hip.copy()
        broken[7, 1] = bad
        with pytest.raises(ValueError, match=rf"p_W_hip_m\[7\] = \([^,]+, {re.escape(repr(bad))}, [^,]+\) is not finite"):
            proxy.step(broken)
        with pytest.raises(ValueError, match=r"p_W_hip_m\[7\] = "):
            mhd.replay_proxy(cube_wall, t_s, broken)
        np.testing.assert_array_equal(proxy.proxy_W_m, before)  # no row was stepped
    with pytest.raises(ValueError, match=r"p_W_hip_m = \(nan, 1, 0\) is not finite"):
        mhd.Proxy(cube_wall, [np.nan, 1.0, 0.0])
    # The dual: the same path without the bad value steps as a fresh proxy does.
    np.testing.assert_array_equal(proxy.step(hip).force_W_N, mhd.Proxy(cube_wall, hip[0]).step(hip).force_W_N)


def test_stepping_releases_the_gil(cube_wall):
    # Pressing into the wall for many ticks keeps step() busy well over 50 ms; with the
    # GIL released the main thread counts meanwhile, with it held it could not count at all.
    rows = 200_000
    hip = np.tile([0.01, 1.0, WALL_Z_M - 0.002], (rows, 1))
    hip[0, 2] = WALL_Z_M + 0.01
    proxy = mhd.Proxy(cube_wall, hip[0])
    started = threading.Event()

    def step():
        started.set()
        proxy.step(hip)

    worker = threading.Thread(target=step)
    worker.start()
    started.wait()
    counted = 0
    while worker.is_alive():
        counted += 1
    worker.join()
    assert counted > 1000
