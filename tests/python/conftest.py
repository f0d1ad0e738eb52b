"""Shared fixtures of the `mhd` module's tests (tests/python/CMakeLists.txt runs them with
PYTHONPATH at the built package, from the repository root)."""

import os
import subprocess

import numpy as np
import pytest

import mhd

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def repo_path(*parts):
    return os.path.join(REPO, *parts)


def needed_env(name):
    """A path the CMake test passes in; the suite is meant to run through ctest."""
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"${name} is not set: run this suite through ctest (tests/python/CMakeLists.txt)")
    return value


def run_cli(*args):
    """The `mhd` command line tool, to compare the module against."""
    return subprocess.run([needed_env("MHD_CLI"), *args], capture_output=True, text=True, cwd=REPO)


@pytest.fixture(scope="session")
def cube_wall():
    return mhd.load_scene(repo_path("scenes", "cube_wall.xml"))


def push_path(rows=400):
    """A push 20 mm into the cube wall's front face (z = -0.3 m) and back out, at 1 kHz:
    z = -0.26 - 0.06 sin(pi s), the path of tests/cli/proxy_replay_command_test.cpp."""
    s = np.arange(rows) / (rows - 1)
    t_s = 0.001 * np.arange(rows)
    hip = np.column_stack([np.full(rows, 0.01), np.ones(rows), -0.26 - 0.06 * np.sin(np.pi * s)])
    return t_s, hip
