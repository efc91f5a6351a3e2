"""Checks of a finished (or running) simulation that say what went wrong in the robot's terms.

Each `judge_*` function returns a Verdict (passed, a sentence, evidence as plain data) — the
grader's checks use these; each `assert_*` raises AssertionError with the sentence — tests use
these. Distances are mm, times seconds of simulation time."""

from __future__ import annotations

import math
import re
import signal as signals
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from eyesim import platform
from eyesim.testing.contacts import Thing


@dataclass
class Verdict:
    passed: bool
    message: str
    evidence: dict = field(default_factory=dict)

    def check(self) -> None:
        if not self.passed:
            raise AssertionError(self.message)


def target_point(
    sim, point=None, marker: int | None = None, object_id: int | None = None
) -> tuple[tuple[float, float], str]:
    """(x, y) in mm and how to name it: a point, a scene marker (1-based) or an object's position."""
    if marker is not None:
        markers = sim.scene.markers
        if not 1 <= marker <= len(markers):
            raise ValueError(f"no marker {marker}: the scene has {len(markers)}")
        found = markers[marker - 1]
        return (found.x, found.y), f"marker {marker} at ({found.x:.0f}, {found.y:.0f})"
    if object_id is not None:
        pose = sim.object(object_id).pose
        return (pose.x, pose.y), f"object {object_id} at ({pose.x:.0f}, {pose.y:.0f})"
    if point is None:
        raise ValueError("a target needs a point, a marker or an object")
    return (float(point[0]), float(point[1])), f"({point[0]:.0f}, {point[1]:.0f})"


def judge_final_pose(
    sim,
    robot,
    tolerance: float,
    point=None,
    marker=None,
    object_id=None,
    heading: float | None = None,
    heading_tolerance: float = 10.0,
) -> Verdict:
    view = sim.robot(robot)
    (x, y), name = target_point(sim, point, marker, object_id)
    pose = view.pose
    distance = pose.distance_to(x, y)
    evidence = {
        "x": round(pose.x, 1),
        "y": round(pose.y, 1),
        "phi": round(pose.phi, 1),
        "distance": round(distance, 1),
        "time": round(sim.time, 3),
    }
    if distance > tolerance:
        return Verdict(
            False,
            f"robot {view.id} ended {distance:.0f} mm from {name} (tolerance {tolerance:g}); "
            f"it ended at ({pose.x:.0f}, {pose.y:.0f})",
            evidence,
        )
    if heading is not None:
        off = abs((pose.phi - heading + 180) % 360 - 180)
        evidence["heading_error"] = round(off, 1)
        if off > heading_tolerance:
            return Verdict(
                False,
                f"robot {view.id} ended facing {pose.phi:.0f} deg, {off:.0f} deg off {heading:g} "
                f"(tolerance {heading_tolerance:g})",
                evidence,
            )
    return Verdict(True, f"robot {view.id} ended {distance:.0f} mm from {name}", evidence)


def judge_reached(
    sim, robot, tolerance: float, point=None, marker=None, object_id=None, before: float | None = None
) -> Verdict:
    view = sim.robot(robot)
    (x, y), name = target_point(sim, point, marker, object_id)
    distance, when = view.closest_approach(x, y, before)
    hit = next(
        (
            p
            for p in view.path
            if (before is None or p.t <= before + 1e-9) and math.hypot(p.x - x, p.y - y) <= tolerance
        ),
        None,
    )
    evidence = {"closest": round(distance, 1), "closest_time": round(when, 3)}
    by = f" by {before:g} s" if before is not None else ""
    if hit is None:
        return Verdict(
            False,
            f"robot {view.id} came no closer than {distance:.0f} mm to {name}{by} "
            f"(closest at {when:.2f} s; tolerance {tolerance:g})",
            evidence,
        )
    evidence["reached_time"] = round(hit.t, 3)
    return Verdict(True, f"robot {view.id} reached {name} at {hit.t:.2f} s", evidence)


def judge_object_pose(sim, object_id: int, tolerance: float, point) -> Verdict:
    pose = sim.object(object_id).pose
    distance = pose.distance_to(*point)
    evidence = {"x": round(pose.x, 1), "y": round(pose.y, 1), "distance": round(distance, 1)}
    where = f"({point[0]:.0f}, {point[1]:.0f})"
    if distance > tolerance:
        return Verdict(
            False,
            f"object {object_id} ended {distance:.0f} mm from {where} (tolerance {tolerance:g}); "
            f"it is at ({pose.x:.0f}, {pose.y:.0f})",
            evidence,
        )
    return Verdict(True, f"object {object_id} ended {distance:.0f} mm from {where}", evidence)


def judge_collisions(sim, robot, with_kind: str = "wall", at_most: int = 0) -> Verdict:
    view = sim.robot(robot)
    contacts = view.contacts(with_kind)
    things = {"wall": "walls", "robot": "other robots", "object": "objects", "any": "anything"}[with_kind]
    me = Thing("robot", view.id)
    listed = ", ".join(f"{c.other(me)} at {c.start:.2f} s" for c in contacts[:5]) + (
        ", ..." if len(contacts) > 5 else ""
    )
    evidence = {"count": len(contacts), "contacts": [c.as_dict() for c in contacts[:20]]}
    if len(contacts) > at_most:
        allowed = "" if at_most == 0 else f" (at most {at_most} allowed)"
        return Verdict(False, f"robot {view.id} touched {things} {len(contacts)} time(s){allowed}: {listed}", evidence)
    return Verdict(True, f"robot {view.id} touched {things} {len(contacts)} time(s)", evidence)


def judge_lcd_text(
    sim, robot, text: str | None = None, regex: str | None = None, row: int | None = None, column: int | None = None
) -> Verdict:
    view = sim.robot(robot)
    rows = view.lcd_text()
    where = rows if row is None else [rows[row][column or 0 :] if row < len(rows) else ""]
    if text is not None:
        text_shown = text.rstrip()  # rows end at their last character: trailing blanks are not text
    found = any(
        (
            re.search(regex, r)
            if regex is not None
            else (r.startswith(text_shown) if column is not None else text_shown in r)
        )
        for r in where
    )
    wanted = f"/{regex}/" if regex is not None else repr(text)
    at = "" if row is None else f" at row {row}" + ("" if column is None else f", column {column}")
    evidence = {"lcd_text": rows}
    shown = "\n".join(f"  {n:2d} |{r}" for n, r in enumerate(rows)) or "  (no text)"
    if not found:
        return Verdict(False, f"robot {view.id}'s LCD does not show {wanted}{at}; it shows:\n{shown}", evidence)
    return Verdict(True, f"robot {view.id}'s LCD shows {wanted}{at}", evidence)


def describe_exit(run) -> str:
    if run is None:
        return "has no program"
    if run.error:
        return run.error
    if run.stopped_by_us:
        return "was still running at the end (stopped)"
    if run.exit_code is None:
        return "is still running"
    if platform.WINDOWS and run.crash is not None:
        return run.crash
    if run.exit_code < 0:
        try:
            name = signals.Signals(-run.exit_code).name
        except ValueError:
            name = f"signal {-run.exit_code}"
        return f"was killed by {name}" + {
            "SIGSEGV": " (a crash: invalid memory access)",
            "SIGXCPU": " (its CPU time limit)",
            "SIGKILL": " (killed)",
            "SIGABRT": " (aborted)",
            "SIGFPE": " (arithmetic error)",
        }.get(name, "")
    return f"exited with code {run.exit_code}"


def judge_exit_code(sim, robot, code: int = 0) -> Verdict:
    view = sim.robot(robot)
    run = view.program
    evidence = {
        "exit_code": view.exit_code,
        "stopped": bool(run and run.stopped_by_us),
        "error": run.error if run else None,
    }
    ok = run is not None and view.exit_code == code and not run.error
    message = f"robot {view.id}'s program {describe_exit(run)}"
    if not ok:
        tail = view.stderr.strip().splitlines()[-5:]
        return Verdict(
            False,
            message
            + f" (expected exit code {code})"
            + ("; its last error output:\n  " + "\n  ".join(tail) if tail else ""),
            evidence,
        )
    return Verdict(True, message, evidence)


def judge_text(
    what: str, content: str | None, contains: str | None = None, equals: str | None = None, regex: str | None = None
) -> Verdict:
    """A text (console output, a file) that must contain, equal or match something."""
    evidence = {"content": None if content is None else content[-2000:]}
    if content is None:
        return Verdict(False, f"{what} does not exist", evidence)
    if equals is not None and content != equals:
        return Verdict(False, f"{what} is {content[:200]!r}, not {equals[:200]!r}", evidence)
    if contains is not None and contains not in content:
        return Verdict(False, f"{what} does not contain {contains!r}; it ends {content[-200:]!r}", evidence)
    if regex is not None and not re.search(regex, content, flags=re.MULTILINE):
        return Verdict(False, f"{what} does not match /{regex}/; it ends {content[-200:]!r}", evidence)
    return Verdict(True, f"{what} is as expected", evidence)


def lcd_difference(actual: np.ndarray, expected: np.ndarray) -> int:
    """How many pixels differ (all pixels when the sizes differ)."""
    if actual.shape != expected.shape:
        return actual.shape[0] * actual.shape[1]
    return int(np.any(actual != expected, axis=2).sum())


def judge_lcd_image(sim, robot, expected: str | Path, save_dir: str | Path, max_different_pixels: int = 0) -> Verdict:
    """The LCD against a PNG; on a mismatch saves actual, expected and a difference image
    (differing pixels red) in `save_dir` and names them."""
    from PIL import Image

    view = sim.robot(robot)
    actual = view.lcd_image()
    wanted = np.asarray(Image.open(expected).convert("RGB"))
    different = lcd_difference(actual, wanted)
    if different <= max_different_pixels:
        return Verdict(True, f"robot {view.id}'s LCD matches {expected}", {"different_pixels": different})
    save_dir = Path(save_dir)
    save_dir.mkdir(parents=True, exist_ok=True)
    paths = {name: save_dir / f"robot{view.id}-lcd-{name}.png" for name in ("actual", "expected", "diff")}
    Image.fromarray(actual).save(paths["actual"])
    Image.fromarray(wanted).save(paths["expected"])
    if actual.shape == wanted.shape:
        diff = (actual // 3).copy()
        diff[np.any(actual != wanted, axis=2)] = (255, 0, 0)
        Image.fromarray(diff).save(paths["diff"])
    names = ", ".join(f"{k}: {v}" for k, v in paths.items() if v.exists())
    return Verdict(
        False,
        f"robot {view.id}'s LCD differs from {expected} in {different} pixels "
        f"(at most {max_different_pixels} allowed); saved {names}",
        {"different_pixels": different, "images": {k: str(v) for k, v in paths.items() if v.exists()}},
    )


# -- for tests: the same checks, raising AssertionError --------------------------------------------
def assert_final_pose(sim, robot, tolerance: float, **target) -> None:
    judge_final_pose(sim, robot, tolerance, **target).check()


def assert_reached(sim, robot, tolerance: float, before: float | None = None, **target) -> None:
    judge_reached(sim, robot, tolerance, before=before, **target).check()


def assert_no_collisions(sim, robot, with_kind: str = "wall") -> None:
    judge_collisions(sim, robot, with_kind, 0).check()


def assert_lcd_shows(
    sim, robot, text: str | None = None, *, regex: str | None = None, row: int | None = None, column: int | None = None
) -> None:
    judge_lcd_text(sim, robot, text, regex, row, column).check()


def assert_lcd_matches(sim, robot, expected: str | Path, save_dir: str | Path, max_different_pixels: int = 0) -> None:
    judge_lcd_image(sim, robot, expected, save_dir, max_different_pixels).check()


def assert_exit_code(sim, robot, code: int = 0) -> None:
    judge_exit_code(sim, robot, code).check()
