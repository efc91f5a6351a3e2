"""Fixtures for the sensor and radio tests: C programs built once, headless `eyesim run` of a scene."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.programs import program_builder, scene_runner

PROGRAMS = Path(__file__).resolve().parent / "programs"


@pytest.fixture(scope="session")
def programs(tmp_path_factory):
    """programs(name) -> sensors/programs/<name>.c built with `eyesim cc` (once per session)."""
    return program_builder(PROGRAMS, tmp_path_factory.mktemp("sensor-programs"))


@pytest.fixture
def run_scene(tmp_path):
    """run_scene(scene, {robot: program}, *args, env=None) -> Run of `eyesim run --headless` in the
    test's tmp_path (support.programs.scene_runner)."""
    return scene_runner(tmp_path)
