"""Fixtures for the sensor and radio tests: C programs built once, headless `eyesim run` of a scene."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from support.programs import program_builder, run_headless
from support.rooms import Run

PROGRAMS = Path(__file__).resolve().parent / "programs"


@pytest.fixture(scope="session")
def programs(tmp_path_factory):
    """programs(name) -> sensors/programs/<name>.c built with `eyesim cc` (once per session)."""
    return program_builder(PROGRAMS, tmp_path_factory.mktemp("sensor-programs"))


@pytest.fixture
def run_scene(tmp_path):
    """run_scene(scene, {robot: program}, *args, env=None) -> Run of `eyesim run --headless`.

    Programs are copied next to the scene first: they run in their own directory, so files they
    write land in the test's tmp_path."""

    def run(
        scene: Path, robot_programs: dict[int, Path], *args: str, env: dict | None = None, timeout: float = 120
    ) -> Run:
        options = []
        for robot, program in robot_programs.items():
            local = tmp_path / program.name
            if not local.exists():
                shutil.copy(program, local)
            options += ["--program", f"{robot}={local}"]
        return Run(run_headless(str(scene), *options, *args, cwd=tmp_path, timeout=timeout, env=env))

    return run
