"""Fixtures for the robot tests: C programs built once with `eyesim cc`, headless runs of scenes
that place our example robots."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.driving import drive_scene
from support.programs import program_builder

PROGRAMS = Path(__file__).resolve().parent / "programs"


@pytest.fixture(scope="session")
def programs(tmp_path_factory):
    """programs(name) -> robot/programs/<name>.c built with `eyesim cc` (once per session)."""
    return program_builder(PROGRAMS, tmp_path_factory.mktemp("robot-programs"))


@pytest.fixture
def drive(tmp_path, programs):
    """drive(placements, {robot: program}, robots=..., extra=..., size=..., wall_height=...): drive_scene
    in the test's own directory."""
    return lambda *args, **kwargs: drive_scene(tmp_path, programs, *args, **kwargs)
