"""Grading specs: what a coordinator gets wrong is reported as file:line and what is wrong,
never as a traceback; the JSON Schema in the package is the one in docs/schemas."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from support.programs import eyesim_command

from eyesim.grade.spec import SCHEMA_PATH, SpecError, load_spec
from eyesim.paths import EXAMPLES_DIR

ROOT = Path(__file__).resolve().parents[2]
SCENE = EXAMPLES_DIR / "scenes" / "wall_follow.sim"

GOOD = f'''title = "t"
[programs.follower]
sources = ["wall_follow.c"]

[[cases]]
name = "one"
scene = "{SCENE}"
robots = [{{ robot = 1, program = "follower" }}]

[[cases.checks]]
kind = "reach"
robot = 1
point = [100, 100]
tolerance = 50
'''


def problems(tmp_path: Path, text: str) -> list[str]:
    spec = tmp_path / "spec.toml"
    spec.write_text(text)
    with pytest.raises(SpecError) as raised:
        load_spec(spec)
    return [p.replace(str(spec), "spec.toml") for p in raised.value.problems]


def test_a_good_spec_loads_with_its_defaults(tmp_path):
    (tmp_path / "spec.toml").write_text(GOOD)
    spec = load_spec(tmp_path / "spec.toml")
    [case] = spec.cases
    assert case.time == 60 and case.wall_clock == 120 and case.robots == [{"robot": 1, "program": "follower"}]
    assert spec.programs["follower"].flags == ("-O2",) and len(case.scene.robots) == 1


def test_bad_toml_names_the_line_and_column(tmp_path):
    assert problems(tmp_path, GOOD.replace("tolerance = 50", "tolerance = ")) == [
        "spec.toml:14:13: not valid TOML: Invalid value"
    ]


def test_an_unknown_check_kind_is_named_with_its_line(tmp_path):
    [problem] = problems(tmp_path, GOOD.replace('kind = "reach"', 'kind = "reachh"'))
    assert problem.startswith(
        "spec.toml:11: cases[0].checks[0].kind: unknown check kind 'reachh' (known: final_pose, reach,"
    )


def test_unknown_keys_and_missing_fields(tmp_path):
    found = problems(tmp_path, GOOD.replace("tolerance = 50", "tolernce = 50"))
    assert "spec.toml:10: cases[0].checks[0]: 'tolerance' is missing" in found
    assert any(p.startswith("spec.toml:10: cases[0].checks[0]: unknown key 'tolernce'") for p in found)


def test_a_missing_program_robot_marker_or_scene_is_reported_against_the_scene(tmp_path):
    text = GOOD.replace('program = "follower"', 'program = "folower"').replace("point = [100, 100]", "marker = 2")
    assert problems(tmp_path, text) == [
        "spec.toml:8: cases[0].robots[0].program: no program 'folower' in [programs] (programs: follower)",
        "spec.toml:13: cases[0].checks[0].marker: scene '" + str(SCENE) + "' has 0 marker(s), no marker 2",
    ]
    assert problems(tmp_path, GOOD.replace("robot = 1\npoint", "robot = 3\npoint")) == [
        f"spec.toml:12: cases[0].checks[0].robot: no robot 3 in scene '{SCENE}'; robots: 1 (S4)"
    ]
    [problem] = problems(tmp_path, GOOD.replace(str(SCENE), "nowhere.sim"))
    assert problem.startswith("spec.toml:7: cases[0].scene: scene 'nowhere.sim' not found")


def test_schema_and_scene_problems_are_reported_in_one_pass(tmp_path):
    """A misspelt key and a robot the scene does not have: both at once, not one round each."""
    text = GOOD.replace("tolerance = 50", "tolernce = 50").replace("robot = 1\npoint", "robot = 3\npoint")
    found = problems(tmp_path, text)
    assert any(p.startswith("spec.toml:10: cases[0].checks[0]: unknown key 'tolernce'") for p in found)
    assert f"spec.toml:12: cases[0].checks[0].robot: no robot 3 in scene '{SCENE}'; robots: 1 (S4)" in found
    found = problems(
        tmp_path, GOOD.replace('name = "one"', "name = 5").replace('program = "follower"', 'program = "folower"')
    )
    assert any("cases[0].name" in p for p in found)
    assert any("no program 'folower'" in p for p in found)


def test_a_custom_python_check_must_define_its_function(tmp_path):
    (tmp_path / "extra.py").write_text("def other(sim):\n    return True\n")
    text = GOOD + '\n[[cases.checks]]\nkind = "python"\nfile = "extra.py"\nfunction = "check"\n'
    assert problems(tmp_path, text) == [
        f"spec.toml:19: cases[0].checks[1].function: {tmp_path / 'extra.py'} defines no function 'check'"
    ]


def test_the_command_prints_the_problems_without_a_traceback(tmp_path):
    spec = tmp_path / "spec.toml"
    spec.write_text(GOOD.replace('kind = "reach"', 'kind = "teleport"'))
    (tmp_path / "subs" / "a").mkdir(parents=True)
    result = subprocess.run(
        eyesim_command("grade", str(spec), str(tmp_path / "subs")), capture_output=True, text=True, cwd=tmp_path
    )
    assert result.returncode == 2
    assert f"{spec}:11: cases[0].checks[0].kind: unknown check kind 'teleport'" in result.stderr
    assert "Traceback" not in result.stderr
    result = subprocess.run(
        eyesim_command("grade", str(tmp_path / "missing.toml"), "."), capture_output=True, text=True, cwd=tmp_path
    )
    assert result.returncode == 2 and "cannot read the grading spec: No such file or directory" in result.stderr


def test_the_schema_is_published_in_the_docs():
    assert (ROOT / "docs" / "schemas" / "grading.schema.json").read_text() == SCHEMA_PATH.read_text()
