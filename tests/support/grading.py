"""`eyesim grade` run as a user runs it, and the wall-following lab of examples/grading."""

from __future__ import annotations

import importlib.util
import subprocess
from pathlib import Path

from support.programs import eyesim_command
from eyesim.paths import EXAMPLES_DIR

GRADING = EXAMPLES_DIR / "grading"
LAB_SPEC = GRADING / "wall_follow_lab.toml"


def lab_submissions_module():
    """examples/grading/lab_submissions.py (a script, not a package module)."""
    spec = importlib.util.spec_from_file_location("lab_submissions", GRADING / "lab_submissions.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def grade(*args: str, cwd: Path, timeout: float = 600) -> subprocess.CompletedProcess:
    return subprocess.run(eyesim_command("grade", *args), capture_output=True, text=True, cwd=cwd, timeout=timeout)


# A one-case spec in the bundled arena: the robot's LCD must say "arrived" (tests of the report and
# of replaying its failed cases), and a submission that arrives and one that gets lost.
ARRIVE_SPEC = """
title = "replays"
[programs.prog]
sources = ["prog.c"]
[limits]
time = 4
[[cases]]
name = "drive"
scene = "default"
robots = [{ robot = 1, program = "prog" }]
[[cases.checks]]
kind = "lcd_text"
robot = 1
text = "arrived"
"""
ARRIVES = '#include "eyebot.h"\nint main(void) { VWStraight(300, 300); VWWait(); LCDPrintf("arrived"); return 0; }\n'
GETS_LOST = '#include "eyebot.h"\nint main(void) { VWTurn(90, 90); VWWait(); LCDPrintf("lost"); return 0; }\n'


def grade_class(root: Path, spec: str, sources: dict[str, str]) -> Path:
    """Grades `sources` (student -> prog.c) against `spec` in `root`; returns the report folder."""
    (root / "spec.toml").write_text(spec)
    for name, source in sources.items():
        (root / "subs" / name).mkdir(parents=True)
        (root / "subs" / name / "prog.c").write_text(source)
    out = root / "report"
    done = grade("spec.toml", "subs", "--out", str(out), cwd=root)
    assert done.returncode == 0, done.stdout + done.stderr
    return out
