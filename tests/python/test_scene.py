"""Reading, validating and compiling scenes from Python: the engine's diagnostics, the same
that `mhd validate` prints, arrive as MhdError / Diagnostic with file:line."""

import os
import re

import pytest

import mhd
from conftest import repo_path, run_cli


def test_read_scene_says_what_the_file_says():
    scene = mhd.read_scene(repo_path("scenes", "dolphin.xml"))
    assert scene.name == "dolphin"
    assert ("device", "sim_phantom") in scene.plugins
    assert ("tracker", "sim_is900") in scene.plugins
    assert scene.max_force_N == 8.5
    assert scene.update_rate_Hz == 1000.0


def test_a_bad_scene_raises_mhd_error_with_the_engines_file_line_message():
    path = "tests/data/scenes/malformed/unknown_attribute.xml"
    with pytest.raises(mhd.MhdError) as caught:
        mhd.read_scene(path)
    cli = run_cli("validate", "--no-meshes", path)
    assert cli.returncode == 1
    # The very lines `mhd validate` prints.
    assert str(caught.value) == cli.stderr.strip()
    [d] = caught.value.diagnostics
    assert (d.file, d.line) == (path, 4)
    assert str(d) == f"{path}:4: error: {d.message}"
    assert caught.value.report is None


def test_validate_lists_every_problem_without_raising():
    path = "tests/data/scenes/malformed/negative_stiffness.xml"
    problems = mhd.validate(path)
    assert [str(d) for d in problems] == run_cli("validate", path).stderr.strip().splitlines()
    assert problems and all(d.line > 0 for d in problems)
    assert mhd.validate(repo_path("scenes", "cube_wall.xml")) == []


@pytest.mark.parametrize("path", ["tests/data/scenes/plugin_errors/typos.xml",
                                  "tests/data/scenes/absurd_settings/server.xml"])
def test_validate_judges_settings_and_plugins_as_the_cli_does(path):
    cli = run_cli("validate", "--no-meshes", path)
    assert cli.returncode == 1
    problems = mhd.validate(path, meshes=False)
    # The folders a missing plugin was looked for in differ by program: mhd's own folder
    # (its installed plugins) is not python's.
    def same(line):
        return re.sub(r"\(looked for (\S+) in [^)]*\)", r"(looked for \1 in ...)", line)
    assert [same(str(d)) for d in problems] == [same(line) for line in cli.stderr.strip().splitlines()]
    assert problems and all(d.line > 0 for d in problems)


def test_validate_finds_plugins_where_the_cli_does():
    # The dual: a scene whose plugins are all found and take their parameters is good to
    # both, with or without meshes.
    path = repo_path("scenes", "dolphin.xml")
    assert run_cli("validate", "--no-meshes", path).returncode == 0
    assert mhd.validate(path, meshes=False) == []
    assert mhd.validate(path, meshes=False, plugin_path=["/nonexistent"]) == []


def test_compile_problems_are_mhd_errors_naming_the_file():
    path = "tests/data/scenes/bad_mesh/empty_mesh.xml"
    scene = mhd.read_scene(path)  # reading checks the mesh exists, not what it holds
    with pytest.raises(mhd.MhdError) as caught:
        mhd.compile_scene(scene, use_cache=False)
    assert str(caught.value) == run_cli("validate", "--no-cache", path).stderr.strip()
    assert caught.value.diagnostics[0].file.endswith(("empty_mesh.xml", "empty.ply"))


def test_read_scene_string_resolves_against_the_given_file(tmp_path):
    xml = """<?xml version="1.0"?>
<scene version="1" name="ball" unit="m">
  <object name="ball"><material stiffness_N_per_m="500"/><sphere radius="0.1"/></object>
</scene>"""
    scene = mhd.read_scene_string(xml, os.path.join(tmp_path, "ball.xml"))
    assert scene.max_force_N is None  # absent: the device's limit
    compiled = mhd.compile_scene(scene)
    assert compiled.max_force_N == 8.5  # no device here: the thesis arm's
    assert compiled.name == "ball"
    assert compiled.object_names == ["ball"]
    assert compiled.triangle_count > 100
    with pytest.raises(mhd.MhdError, match=r"ball\.xml:2: error: "):
        mhd.read_scene_string(xml.replace('version="1" ', ""), os.path.join(tmp_path, "ball.xml"))


def test_a_compiled_scene_keeps_its_description(cube_wall):
    assert cube_wall.scene.name == "cube_wall"
    assert cube_wall.object_names == ["cube", "floor"]
    assert cube_wall.skin_m == 1e-6
    assert cube_wall.max_force_N == 8.5
