"""Fixtures for the part kinds' tests (tests/parts/<kind>/): the C programs of the kind's
`programs/` folder built once, headless `eyesim run` of a scene, and driving scenes."""

from __future__ import annotations

import pytest
from support.driving import drive_scene
from support.programs import program_builder, scene_runner


@pytest.fixture(scope="session")
def builders(tmp_path_factory):
    """A program builder per programs folder, for the whole session."""
    made: dict = {}

    def builder(folder):
        if folder not in made:
            made[folder] = program_builder(folder, tmp_path_factory.mktemp(f"{folder.parent.name}-programs"))
        return made[folder]

    return builder


@pytest.fixture
def programs(request, builders):
    """programs(name) -> <name>.c of the `programs` folder beside the test module, built with
    `eyesim cc` (once per session)."""
    return builders(request.path.parent / "programs")


@pytest.fixture
def run_scene(tmp_path):
    """run_scene(scene, {robot: program}, *args, env=None) -> Run of `eyesim run --headless` in the
    test's tmp_path (support.programs.scene_runner)."""
    return scene_runner(tmp_path)


@pytest.fixture
def drive(tmp_path, programs):
    """drive(placements, {robot: program}, robots=..., extra=..., size=..., wall_height=...): drive_scene
    in the test's own directory."""
    return lambda *args, **kwargs: drive_scene(tmp_path, programs, *args, **kwargs)
