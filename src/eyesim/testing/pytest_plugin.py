"""The pytest plugin EyeSim installs (entry point `pytest11`): fixtures for simulations and C
programs, and assertions with messages in the robot's terms (docs/testing.md).

    def test_reaches_the_goal(eyesim_sim, eyesim_cc):
        sim = eyesim_sim("maze.sim")
        sim.program(1, eyesim_cc("solver.c"))
        sim.run(until=60)
        eyesim.testing.assertions.assert_reached(sim, 1, 100, marker=1, before=45)

Imports stay inside the fixtures: every pytest run in an environment with EyeSim loads this
module, and it must not slow down test suites that never use it."""

from __future__ import annotations

import pytest


@pytest.fixture
def eyesim_sim():
    """eyesim_sim(scene=None, **options) -> eyesim.Simulation, closed after the test."""
    from eyesim.testing import Simulation

    made = []

    def make(scene=None, **options):
        sim = Simulation(scene, **options)
        made.append(sim)
        return sim

    yield make
    for sim in made:
        sim.close()


@pytest.fixture(scope="session")
def _eyesim_build_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("eyesim-cc")


@pytest.fixture(scope="session")
def eyesim_cc(_eyesim_build_dir):
    """eyesim_cc(source, *flags, language='cc') -> the executable `eyesim cc` built from a C file
    (language='c++' for C++); built once per session and set of flags. A compile error fails
    the test with the compiler's messages."""
    from pathlib import Path

    from eyesim.testing import CompileError, compile_program

    built: dict[tuple, Path] = {}  # (source, flags, language) -> executable

    def build(source, *flags, language: str = "cc"):
        source = Path(source).resolve()
        key = (source, flags, language)
        if key not in built:
            output = _eyesim_build_dir / f"{source.stem}-{len(built)}"
            try:
                built[key] = compile_program(source, output, flags or ("-O2",), language)
            except CompileError as error:
                pytest.fail(str(error), pytrace=False)
        return built[key]

    return build


@pytest.fixture
def eyesim_artifacts(tmp_path):
    """A directory for images a failing check saves (LCD mismatches)."""
    path = tmp_path / "eyesim-artifacts"
    path.mkdir()
    return path
