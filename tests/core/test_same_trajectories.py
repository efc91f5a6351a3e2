"""Deterministic runs repeat bit for bit: the digests of fixed runs (tests/core/deterministic_runs.py)
match those the engine made before it was split into its step loop, request handling and schedules
(tests/core/trajectories.json)."""

import json
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def test_deterministic_runs_match_the_stored_digests():
    stored = json.loads((HERE / "trajectories.json").read_text())
    result = subprocess.run(
        [sys.executable, str(HERE / "deterministic_runs.py")],
        capture_output=True,
        text=True,
        env=dict(os.environ, MUJOCO_GL="disable"),
        timeout=600,
    )
    assert result.returncode == 0, result.stderr
    found = json.loads(result.stdout)
    assert found["mujoco"] == stored["mujoco"], "the digests were made with another MuJoCo: write them again"
    differ = [
        f"{name}: {key} {stored_run[key]!r} -> {found['runs'][name][key]!r}"
        for name, stored_run in stored["runs"].items()
        for key in stored_run
        if found["runs"][name][key] != stored_run[key]
    ]
    assert not differ, "deterministic runs changed:\n" + "\n".join(differ)
