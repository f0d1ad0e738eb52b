"""The haptic server on simulated plugins from Python: a run for N seconds with its report
and recording, a fault that names the plugin and its scene line, a scene the server
cannot open, and Ctrl-C."""

import re
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import mhd
from conftest import REPO, needed_env, repo_path


def test_run_the_dolphin_on_simulated_hardware(tmp_path):
    recording = tmp_path / "run.csv"
    report = mhd.run_server(mhd.load_scene(repo_path("scenes", "dolphin.xml")), duration_s=1.0, recording=recording)
    assert report.ended_by == "duration"
    assert report.error is None
    assert 0.9 <= report.status.elapsed_s < 3.0
    assert report.status.ticks > 500  # 1 kHz, however loaded the machine
    assert report.zero_force_sent and report.base_stop_sent
    assert report.fault_ticks == 0
    rec = mhd.read_recording(recording)
    assert len(rec) == report.recording_rows > 500
    assert np.all(np.diff(rec["t_s"]) > 0)
    startup = rec["tracker_age_s"] < 0
    assert np.all(np.isnan(rec["hip_x_m"][startup]))  # no base pose yet: no HIP
    assert np.all(np.isfinite(rec["hip_x_m"][~startup])) and (~startup).sum() > 400


def test_a_fault_raises_mhd_error_naming_plugin_and_scene_line():
    scene = mhd.load_scene("tests/data/server/device_fault.xml")
    with pytest.raises(mhd.MhdError) as caught:
        mhd.run_server(scene, duration_s=20.0, plugin_path=[needed_env("MHD_TEST_FAULT_PLUGIN_DIR")])
    assert re.fullmatch(r"tests/data/server/device_fault\.xml:[0-9]+: error: plugin 'fault_device': device_read "
                        r"returned a non-finite p_D_tool_m\[1\]", str(caught.value))
    report = caught.value.report
    assert report.ended_by == "fault"
    assert report.status.elapsed_s < 5.0  # ended by the fault, not the 20 s
    assert report.zero_force_sent and report.base_stop_sent


def test_a_scene_without_plugins_cannot_run(cube_wall):
    with pytest.raises(mhd.MhdError, match=r"cube_wall\.xml.*error: ") as caught:
        mhd.run_server(cube_wall, duration_s=1.0)
    assert caught.value.diagnostics and caught.value.report is None


def test_duration_must_be_positive(cube_wall):
    with pytest.raises(ValueError, match="duration_s must be finite and > 0"):
        mhd.run_server(cube_wall, duration_s=0.0)


def test_ctrl_c_stops_the_run_safely_and_raises_keyboard_interrupt():
    script = (
        "import sys, time, mhd\n"
        "scene = mhd.load_scene('scenes/dolphin.xml')\n"
        "print('running', flush=True)\n"
        "t0 = time.monotonic()\n"
        "try:\n"
        "    mhd.run_server(scene, duration_s=60.0)\n"
        "except KeyboardInterrupt:\n"
        "    print(f'interrupted after {time.monotonic() - t0:.1f} s', flush=True)\n"
        "    sys.exit(7)\n")
    run = subprocess.Popen([sys.executable, "-c", script], cwd=REPO, stdout=subprocess.PIPE, text=True)
    assert run.stdout.readline() == "running\n"
    time.sleep(1.0)
    run.send_signal(signal.SIGINT)
    out, _ = run.communicate(timeout=30)
    assert run.returncode == 7
    assert re.fullmatch(r"interrupted after [0-9.]+ s\n", out)
    assert float(out.split()[2]) < 30.0  # stopped by the signal, not the 60 s
