"""Starting and supervising robot programs: environment, console output, exit codes."""

from __future__ import annotations

import os
import subprocess
import sys
import threading
from dataclasses import dataclass
from pathlib import Path

from eyesim import paths


@dataclass
class ProgramRun:
    robot_id: int
    path: Path
    process: subprocess.Popen | None = None
    exit_code: int | None = None
    stopped_by_us: bool = False
    error: str | None = None

    @property
    def name(self) -> str:
        return self.path.name

    @property
    def failed(self) -> bool:
        if self.error:
            return True
        return self.exit_code not in (None, 0) and not self.stopped_by_us


def command_for(path: Path) -> list[str]:
    """How to start a program: Python files with this Python, anything else as an executable."""
    if path.suffix == ".py":
        return [sys.executable, str(path)]
    return [str(path)]


def program_environment(host: str, port: int, robot_id: int) -> dict[str, str]:
    """Ours plus where the simulator is, and libeyesim's directory first on LD_LIBRARY_PATH: an
    EyeSim-era eye.py beside a Python program loads the library by name (CDLL("libeyesim.so")),
    and so do C programs linked without `eyesim cc`'s rpath."""
    env = dict(os.environ, EYESIM_HOST=host, EYESIM_PORT=str(port), EYESIM_ROBOT=str(robot_id))
    env.setdefault("PYTHONUNBUFFERED", "1")
    env["LD_LIBRARY_PATH"] = os.pathsep.join(
        part for part in (str(paths.robios_lib_dir()), os.environ.get("LD_LIBRARY_PATH")) if part)
    return env


class Launcher:
    """Starts each program for its robot and forwards its output to the console and the viewer."""

    def __init__(self, sim, host: str, port: int, echo: bool = True):
        self.sim = sim
        self.host = host
        self.port = port
        self.echo = echo
        self.runs: list[ProgramRun] = []
        self._lock = threading.Lock()
        self._threads: list[threading.Thread] = []

    def start(self, robot_id: int, path: str | Path) -> ProgramRun:
        run = ProgramRun(robot_id, Path(path))
        self.runs.append(run)
        try:
            found = run.path.is_file()
        except OSError as error:  # a name the file system refuses (too long), not just a missing file
            found = False
            path = f"{str(path)[:80]}... ({error.strerror})" if len(str(path)) > 80 else f"{path} ({error.strerror})"
        if not found:
            run.error = f"program not found: {path}"
            self._print(run, "stderr", f"eyesim: {run.error}\n")
            return run
        env = program_environment(self.host, self.port, robot_id)
        robot_id_ = robot_id
        self.sim.call(lambda sim: sim.expected_programs.add(robot_id_))
        run.path = run.path.resolve()
        try:
            run.process = subprocess.Popen(command_for(run.path), cwd=run.path.parent, env=env,
                                           stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                           stderr=subprocess.PIPE)
        except OSError as error:
            run.error = f"cannot start {run.path}: {error.strerror}"
            self._print(run, "stderr", f"eyesim: {run.error}\n")
            self.sim.call(lambda sim: sim.program_gone(robot_id_))
            return run
        self.sim.call(lambda sim: sim.events.program(robot_id_, "started", run.name, None))
        for stream in ("stdout", "stderr"):
            thread = threading.Thread(target=self._forward, args=(run, stream), daemon=True)
            thread.start()
            self._threads.append(thread)
        waiter = threading.Thread(target=self._wait, args=(run,), daemon=True)
        waiter.start()
        self._threads.append(waiter)
        return run

    def _forward(self, run: ProgramRun, stream: str) -> None:
        pipe = getattr(run.process, stream)
        for raw in iter(pipe.readline, b""):
            self._print(run, stream, raw.decode("utf-8", errors="replace"))
        pipe.close()

    def _print(self, run: ProgramRun, stream: str, text: str) -> None:
        if self.echo:
            with self._lock:
                target = sys.stdout if stream == "stdout" else sys.stderr
                target.write(f"[robot {run.robot_id}] {text.rstrip(chr(10))}\n")
                target.flush()
        robot_id = run.robot_id
        self.sim.call(lambda sim: sim.events.console(robot_id, stream, text))

    def _wait(self, run: ProgramRun) -> None:
        run.exit_code = run.process.wait()
        robot_id = run.robot_id

        def exited(sim):
            sim.events.program(robot_id, "exited", run.name, run.exit_code)
            sim.program_gone(robot_id)

        self.sim.call(exited)

    @property
    def all_exited(self) -> bool:
        return all(run.process is None or run.process.poll() is not None for run in self.runs)

    def stop_all(self, grace: float = 2.0, let_finish: float = 0.0) -> None:
        """Stop programs still running (the run is over) and wait for their output to drain.

        `let_finish`: seconds to wait first for programs that are ending by themselves (the run
        ended because they closed their connections)."""
        for run in self.runs:
            if run.process is not None and let_finish > 0:
                try:
                    run.process.wait(timeout=let_finish)
                except subprocess.TimeoutExpired:
                    pass
        for run in self.runs:
            if run.process is not None and run.process.poll() is None:
                run.stopped_by_us = True
                run.process.terminate()
        for run in self.runs:
            if run.process is not None:
                try:
                    run.process.wait(timeout=grace)
                except subprocess.TimeoutExpired:
                    run.process.kill()
                    run.process.wait()
        for thread in self._threads:
            thread.join(timeout=grace)

