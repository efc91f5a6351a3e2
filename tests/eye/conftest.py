"""Fixtures for the Python `eye` tests: the C-library fixtures of tests/c (building libeyesim first
when the development build is the one in use), and running Python robot programs."""

from __future__ import annotations

import contextlib
import importlib.util
import subprocess
import sys
import textwrap
import threading
from pathlib import Path

import pytest
from support.scenes import arena
from support.simulator import running_simulation

_spec = importlib.util.spec_from_file_location("c_library_fixtures", Path(__file__).parents[1] / "c" / "conftest.py")
_c_fixtures = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_c_fixtures)

robios_prefix = _c_fixtures.robios_prefix
compiler = _c_fixtures.compiler
program_env = _c_fixtures.program_env


@pytest.fixture(scope="session")
def eye(robios_prefix):
    """The eye module, imported once the C library it loads is built."""
    import eye as module

    return module


class PythonRun:
    """A Python robot program run against an in-process simulator; the simulation stays up for checks."""

    def __init__(self, sim, results: dict[int, subprocess.CompletedProcess]):
        self.sim = sim
        self.results = results

    def output(self, robot: int = 1) -> dict[str, list[str]]:
        """The program's printed lines, by their first word."""
        lines = self.results[robot].stdout.splitlines()
        return {line.split()[0]: line.split()[1:] for line in lines if line.strip()}

    def on_sim(self, action):
        """action(sim), run on the simulation thread (so the state is consistent); its result."""
        done, box = threading.Event(), []

        def run(sim):
            try:
                box.append(action(sim))
            finally:
                done.set()

        self.sim.call(run)
        assert done.wait(10), "the simulation thread did not answer"
        return box[0] if box else None


@pytest.fixture
def run_python(robios_prefix, tmp_path):
    """run_python({robot: source}, scene=..., setup=fn(sim), inputs=[(seconds, fn(sim))]): runs Python
    programs (one per robot, at the same time) against a deterministic in-process simulator, with
    scripted input at simulation times. Returns a PythonRun once every program has ended."""
    stack = contextlib.ExitStack()

    def run(programs: dict[int, str] | str, scene=None, setup=None, inputs=(), timeout: float = 60) -> PythonRun:
        if isinstance(programs, str):
            programs = {1: programs}
        sim, port = stack.enter_context(running_simulation(scene or arena(), "deterministic", expect=tuple(programs)))
        if setup is not None:
            sim.call(setup)
        for seconds, action in inputs:
            sim.call(lambda s, at=round(seconds * 1e6), act=action: s.schedule(at, act))
        processes = {}
        for robot, source in programs.items():
            path = tmp_path / f"robot{robot}.py"
            path.write_text(textwrap.dedent(source))
            env = program_env(
                EYESIM_HOST="127.0.0.1",
                EYESIM_PORT=str(port),
                EYESIM_ROBOT=str(robot),
                EYESIM_TOKEN=sim.program_token,
                PYTHONUNBUFFERED="1",
            )
            processes[robot] = subprocess.Popen(
                [sys.executable, str(path)],
                cwd=tmp_path,
                env=env,
                text=True,
                stdout=subprocess.PIPE,
                stderr=subprocess.PIPE,
            )
        results = {}
        for robot, process in processes.items():
            try:
                out, err = process.communicate(timeout=timeout)
            except subprocess.TimeoutExpired:
                process.kill()
                out, err = process.communicate()
                pytest.fail(f"robot {robot}'s program did not end:\n{out}\n{err}")
            results[robot] = subprocess.CompletedProcess(process.args, process.returncode, out, err)
        return PythonRun(sim, results)

    yield run
    stack.close()
