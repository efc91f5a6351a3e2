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
