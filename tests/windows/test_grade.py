"""`eyesim grade` under Wine: a correct and a crashing Python submission, every limit set (C
submissions need `eyesim cc`, whose zig.exe Wine 8 cannot run)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from wine_sim import HERE

SPEC = HERE / "grading" / "drive.toml"


def test_grading_scores_a_correct_and_a_crashing_submission(windows, tmp_path):
    shutil.copytree(HERE / "grading" / "submissions", tmp_path / "submissions")
    result = windows.run(
        "grade", windows.path(SPEC), "submissions", "--out", "report", "--workers", "2", cwd=tmp_path, timeout=400
    )
    assert result.returncode == 0, result.stdout + result.stderr
    report = json.loads((tmp_path / "report" / "report.json").read_text())
    students = {student["name"]: student for student in report["students"]}
    assert sorted(students) == ["correct", "crashing"]

    correct = students["correct"]
    assert correct["score"] == 100.0, correct
    [case] = correct["cases"]
    assert case["status"] == "ok" and case["programs"]["1"]["exit_code"] == 0
    assert all(check["passed"] for check in case["checks"]), case["checks"]
    assert case["robots"]["1"]["lcd_text"][0] == "done"

    crashing = students["crashing"]
    [case] = crashing["cases"]
    assert case["status"] == "crashed", case
    assert case["programs"]["1"]["crashed"]
    checks = {check["name"]: check for check in case["checks"]}
    assert checks["reaches 900,500"]["passed"]  # it drove before it crashed
    assert not checks["says done"]["passed"] and not checks["exits cleanly"]["passed"]
    assert "access violation" in checks["exits cleanly"]["message"], checks["exits cleanly"]
    assert crashing["score"] == round(100 / 3, 2)

    # The reports beside report.json, with the final LCD of each case.
    out = tmp_path / "report"
    assert "crashed" in (out / "index.html").read_text()
    assert (out / "cases" / "correct" / "ahead" / "robot1-lcd.png").stat().st_size > 500
    assert "correct" in result.stdout and "100.0" in result.stdout


def test_the_spec_is_checked_before_anything_runs(windows, tmp_path):
    spec = tmp_path / "broken.toml"
    spec.write_text(Path(SPEC).read_text().replace('kind = "reach"', 'kind = "reachh"'))
    (tmp_path / "submissions").mkdir()
    result = windows.run("grade", "broken.toml", "submissions", cwd=tmp_path)
    assert result.returncode == 2, result.stdout + result.stderr
    assert "unknown check kind 'reachh'" in result.stderr
