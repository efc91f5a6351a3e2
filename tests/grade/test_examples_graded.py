"""The project's regression pipeline: every program in examples/programs is graded against its
expected behaviour (examples/grading/examples.toml) with `eyesim grade`; a change of behaviour
fails here with the check that broke and its evidence."""

from __future__ import annotations

import re
import shutil


from support.grading import GRADING, grade

from eyesim.grade.spec import tomllib  # the stdlib module, or tomli before Python 3.11

EXAMPLES = GRADING.parent
SPEC = GRADING / "examples.toml"


def test_every_example_program_has_expected_behaviour_in_the_spec():
    spec = tomllib.loads(SPEC.read_text())
    graded = {source for program in spec["programs"].values() for source in program["sources"]}
    run = {entry["program"] for case in spec["cases"] for entry in case["robots"]}
    assert graded == {p.name for p in (EXAMPLES / "programs").glob("*.c")}
    assert run == set(spec["programs"])


def test_the_examples_behave_as_expected(tmp_path):
    result = grade(
        str(SPEC),
        "--submission",
        str(EXAMPLES / "programs"),
        "--out",
        str(tmp_path / "report"),
        "--workers",
        "2",
        "--require-pass",
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stderr  # FAILED <case>: <check>: <what went wrong>
    assert re.search(r"^programs +100\.0  \(48/48 checks\)$", result.stdout, flags=re.MULTILINE), result.stdout


def test_a_behaviour_change_fails_with_its_evidence(tmp_path):
    changed = tmp_path / "programs"
    shutil.copytree(EXAMPLES / "programs", changed)
    source = changed / "menu_demo.c"
    source.write_text(source.read_text().replace("VWTurn(90, 90);", "VWTurn(80, 90);"))
    result = grade(
        str(SPEC),
        "--submission",
        str(changed),
        "--case",
        "menu_demo",
        "--out",
        str(tmp_path / "report"),
        "--require-pass",
        cwd=tmp_path,
    )
    assert result.returncode == 1
    assert re.search(
        r"FAILED programs/menu_demo: DRIVE: 200 mm, then TURN: 90 degrees: robot 1 ended facing 8\d deg, "
        r"\d+ deg off 90 \(tolerance 2\)",
        result.stderr,
    ), result.stderr
    assert "eyesim grade: 1 case(s) graded" in result.stdout
