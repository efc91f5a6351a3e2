"""`eyesim grade` on the wall-following lab (examples/grading): correct scores for correct,
slow, broken, crashing, hanging, bumping and misnamed submissions, readable reports, resuming."""

from __future__ import annotations

import json
import shutil
import xml.etree.ElementTree as ET

from support.grading import LAB_SPEC, grade


def by_student(report: dict) -> dict:
    return {s["name"]: s for s in report["students"]}


def case(student: dict, name: str = "sensor-lab") -> dict:
    return next(c for c in student["cases"] if c["case"] == name)


def check(case_result: dict, name: str) -> dict:
    return next(c for c in case_result["checks"] if c["name"] == name)


def test_every_kind_of_submission_gets_the_score_it_deserves(graded_lab):
    _, report, _ = graded_lab
    students = by_student(report)
    assert students["good"]["score"] == 100.0 and students["good"]["complete"]
    for name in ("compile_error", "misnamed"):
        assert students[name]["score"] == 0.0
    # slow: late at both places, but off the walls and ending properly: 5 of 9 and 3 of 7 of the weight
    assert students["slow"]["score"] == round(100 * (5 / 9 + 3 / 7) / 2, 2)
    assert students["good"]["score"] > students["slow"]["score"] > students["crash"]["score"] > 0
    assert students["good"]["score"] > students["bumper"]["score"] > 0
    slow = case(students["slow"])
    assert not check(slow, "follows the north wall east")["passed"]
    assert check(slow, "never touches a wall")["passed"] and check(slow, "ends with KEY4")["passed"]


def test_failures_carry_their_evidence(graded_lab):
    _, report, _ = graded_lab
    students = by_student(report)

    broken = case(students["compile_error"])
    assert broken["status"] == "compile_error"
    assert (
        "wall_follow.c:" in broken["build"]["follower"]["output"] and "error" in broken["build"]["follower"]["output"]
    )
    assert "/tmp" not in broken["build"]["follower"]["output"]  # names the student's file, not our directory
    assert all(c["message"] == "not run: program 'follower' does not compile" for c in broken["checks"])

    misnamed = case(students["misnamed"])
    assert misnamed["status"] == "missing_sources"
    assert (
        "no file matching 'wall_follow.c' in the submission (its files: wallfollow.c)"
        in misnamed["build"]["follower"]["output"]
    )

    crash = case(students["crash"])
    assert crash["status"] == "crashed" and crash["programs"]["1"]["crashed"]
    assert "SIGSEGV" in check(crash, "ends with KEY4")["message"]
    assert crash["end"] == {"reason": "programs", "time": 5.008}  # the first loop past 5 s, calls included

    hang = case(students["hang"])
    assert hang["status"] == "cpu_limit"
    assert "SIGXCPU (its CPU time limit)" in check(hang, "ends with KEY4")["message"]
    assert hang["end"]["time"] < 3.1  # deterministic time stood still while it computed

    bumper = case(students["bumper"])
    collisions = check(bumper, "never touches a wall")
    assert not collisions["passed"] and collisions["evidence"]["count"] == 1
    assert collisions["message"].startswith("robot 1 touched walls 1 time(s): wall 2 at 7.")

    good = case(students["good"])
    assert good["status"] == "ok" and good["programs"]["1"]["exit_code"] == 0
    assert good["robots"]["1"]["lcd_text"][0] == "Wall following: left wall at 200 mm"
    assert check(good, "turns the south-east corner")["evidence"]["reached_time"] < 17


def test_reports_json_junit_html_and_images(graded_lab):
    out, report, process = graded_lab
    suites = ET.parse(out / "junit.xml").getroot()
    assert suites.get("tests") == "70"  # 7 students x (6 + 4) checks
    assert suites.get("errors") == "20"  # the checks of the two that did not build
    failed = sum(not c["passed"] for s in report["students"] for k in s["cases"] for c in k["checks"])
    assert int(suites.get("failures")) == failed - 20
    crash = next(s for s in suites if s.get("name") == "crash")
    assert any(
        f.get("message", "").startswith("robot 1's program was killed by SIGSEGV") for f in crash.iter("failure")
    )
    html = (out / "index.html").read_text()
    assert "<td class='score total'>100.0</td>" in html and "compile error</span>" in html
    for name in ("robot1-lcd.png", "trajectory.svg"):
        assert (out / "cases" / "good" / "sensor-lab" / name).stat().st_size > 1000
        assert f"cases/good/sensor-lab/{name}" in html
    assert "[1/14]" in process.stderr and "\r" not in process.stderr  # plain progress lines off a terminal
    assert "\ngood            100.0  (10/10 checks)\n" in process.stdout


def test_an_interrupted_grading_resumes_with_what_is_missing(lab, graded_lab, tmp_path):
    out, report, _ = graded_lab
    copy = tmp_path / "report"
    shutil.copytree(out, copy)
    (copy / "cases" / "crash" / "sensor-lab.json").unlink()  # as if stopped before this case ended
    (copy / "cases" / "slow" / "noisy-psd.json").write_text("{ half written")
    result = grade(str(LAB_SPEC), str(lab[0]), "--out", str(copy), "--require-pass", cwd=tmp_path)
    assert "2 case(s) graded, 12 reused" in result.stdout, result.stdout + result.stderr
    assert result.returncode == 1  # --require-pass: some checks fail
    assert "FAILED crash/sensor-lab: ends with KEY4: robot 1's program was killed by SIGSEGV" in result.stderr
    again = json.loads((copy / "report.json").read_text())
    assert [s["score"] for s in again["students"]] == [s["score"] for s in report["students"]]


def test_failed_cases_keep_a_recording_of_their_run_at_the_grading_rates(graded_lab):
    from eyesim.grade.case_run import RECORDING_LCD_RATE, RECORDING_POSE_RATE
    from eyesim.record import Recording

    out, report, _ = graded_lab
    students = by_student(report)
    for name in ("slow", "bumper", "crash", "hang"):  # recorded while graded, not run again
        files = case(students[name])["files"]
        with Recording(out / files["case.mcap"]) as recording:
            settings = recording.metadata["eyesim"]
            assert float(settings["pose_rate_hz"]) == RECORDING_POSE_RATE
            assert float(settings["lcd_rate_hz"]) == RECORDING_LCD_RATE
            end = case(students[name])["end"]["time"]
            assert abs(recording.duration_s - end) < 0.1, (name, recording.duration_s, end)
    assert "case.mcap" not in case(students["good"])["files"]
    assert "case.mcap" not in case(students["compile_error"])["files"]  # nothing ran
