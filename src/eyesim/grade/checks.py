"""The grading spec's check kinds: each turns a finished simulation into a scored result with
its evidence (the judge_* functions of eyesim.testing.assertions do the measuring)."""

from __future__ import annotations

import traceback
from dataclasses import dataclass
from pathlib import Path

from eyesim.testing import assertions as a


@dataclass
class ScoredVerdict(a.Verdict):
    """A custom check's verdict with its score 0..1 (the other kinds score 1 when passed, else 0)."""

    score: float = 0.0


def _target(check: dict) -> dict:
    return {"point": check.get("point"), "marker": check.get("marker"), "object_id": check.get("object")}


def final_pose(sim, check, context):
    return a.judge_final_pose(
        sim,
        check["robot"],
        check["tolerance"],
        heading=check.get("heading"),
        heading_tolerance=check.get("heading_tolerance", 10.0),
        **_target(check),
    )


def reach(sim, check, context):
    return a.judge_reached(sim, check["robot"], check["tolerance"], before=check.get("before"), **_target(check))


def no_collision(sim, check, context):
    return a.judge_collisions(sim, check["robot"], check.get("with", "wall"), check.get("at_most", 0))


def lcd_text(sim, check, context):
    return a.judge_lcd_text(
        sim, check["robot"], check.get("text"), check.get("regex"), check.get("row"), check.get("column")
    )


def exit_code(sim, check, context):
    return a.judge_exit_code(sim, check["robot"], check.get("code", 0))


def file(sim, check, context):
    path = context["workdir"] / check["path"]
    try:
        content = path.read_bytes().decode("utf-8", errors="replace") if path.is_file() else None
    except OSError:
        content = None
    what = f"file {check['path']!r} of robot {check['robot']}'s program"
    return a.judge_text(what, content, check.get("contains"), check.get("equals"), check.get("regex"))


def console(sim, check, context):
    stream = check.get("stream", "stdout")
    robot = sim.robot(check["robot"])
    content = robot.stdout if stream == "stdout" else robot.stderr
    return a.judge_text(
        f"robot {robot.id}'s {stream}", content, check.get("contains"), check.get("equals"), check.get("regex")
    )


def object_pose(sim, check, context):
    return a.judge_object_pose(sim, check["object"], check["tolerance"], check["point"])


def python(sim, check, context):
    """A function of the spec's own: function(sim, **params) returning True/False, a score
    0..1, or (score, message)."""
    namespace = context["python_modules"].get(check["file"])
    if namespace is None:
        namespace = {"__name__": f"eyesim_check_{Path(check['file']).stem}"}
        exec(compile(context["python_checks"][check["file"]], check["file"], "exec"), namespace)
        context["python_modules"][check["file"]] = namespace
    try:
        value = namespace[check["function"]](sim, **check.get("params", {}))
    except Exception as error:
        frames = traceback.extract_tb(error.__traceback__)
        where = next((f"{f.filename}:{f.lineno}" for f in reversed(frames) if f.filename == check["file"]), "")
        return a.Verdict(
            False,
            f"custom check {check['function']} raised {type(error).__name__}: {error}"
            + (f" ({where})" if where else ""),
            {},
        )
    message = None
    if isinstance(value, tuple):
        value, message = value
    score = float(value)
    if not 0 <= score <= 1:
        return a.Verdict(False, f"custom check {check['function']} returned {value!r}, not a score 0..1", {})
    return ScoredVerdict(score == 1, message or f"custom check {check['function']}: {score:g}", {"score": score}, score)


KINDS = {
    "final_pose": final_pose,
    "reach": reach,
    "no_collision": no_collision,
    "lcd_text": lcd_text,
    "exit_code": exit_code,
    "file": file,
    "console": console,
    "object_pose": object_pose,
    "python": python,
}


def describe(check: dict) -> str:
    """A check's name: its own, else made from its kind and target."""
    if check.get("name"):
        return check["name"]
    parts = [check["kind"]]
    for key in ("robot", "object", "point", "marker", "text", "regex", "path", "with", "before"):
        if key in check:
            parts.append(f"{key}={check[key]}")
    return " ".join(parts)


def judge(sim, check: dict, context: dict) -> dict:
    """The check's result: name, kind, weight, passed, score 0..1, message, evidence."""
    weight = check.get("weight", 1.0)
    try:
        verdict = KINDS[check["kind"]](sim, check, context)
    except Exception as error:  # a check must never end the grading of the other checks
        verdict = a.Verdict(False, f"the check could not be evaluated: {type(error).__name__}: {error}", {})
    score = verdict.score if isinstance(verdict, ScoredVerdict) else 1.0 if verdict.passed else 0.0
    return {
        "name": describe(check),
        "kind": check["kind"],
        "weight": weight,
        "passed": verdict.passed,
        "score": score,
        "message": verdict.message,
        "evidence": verdict.evidence,
    }
