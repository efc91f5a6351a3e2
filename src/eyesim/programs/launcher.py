"""Starting and supervising robot programs: environment, console output, exit codes."""

from __future__ import annotations

import os
import subprocess
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, cast

from eyesim import paths, platform
from eyesim.programs import sources
from eyesim.programs.program_output import ProgramOutput

OUTPUT_LIMIT = 1 << 20  # characters of a program's output kept per stream (a runaway printf loop)
# Seconds a program whose connection to the simulator has closed gets to exit when the run ends
# (`--until` came while it was exiting): its own exit code, not "still running (stopped)".
ENDING_GRACE = 3.0


@dataclass(frozen=True)
class ProgramOptions:
    """How a program starts beyond its path: arguments, input, directory, environment and limits.

    `stdin` (text or bytes) is written to the program's standard input, which is then closed;
    None gives it no input. `cwd` defaults to the program's directory; `env` adds to (and
    overrides) the environment. `cpu_seconds` and `memory_bytes` are resource limits of the
    program's process (RLIMIT_CPU, RLIMIT_AS; a Job Object's limits on Windows). With `own_group`
    (the default) the program gets a process group (Windows: a job) of its own, so that stopping it
    also stops the processes it started; without, it stays in ours (a graded case's programs: its
    sandbox ends them all at once)."""

    args: tuple[str, ...] = ()
    stdin: str | bytes | None = None
    cwd: str | Path | None = None
    env: dict[str, str] = field(default_factory=dict)
    cpu_seconds: float | None = None
    memory_bytes: int | None = None
    own_group: bool = True
    processes: int | None = None  # RLIMIT_NPROC (platform.Limits says what it counts)
    file_bytes: int | None = None  # RLIMIT_FSIZE: the largest file the program may write

    @property
    def limits(self) -> platform.Limits:
        return platform.Limits(self.cpu_seconds, self.memory_bytes, self.processes, self.file_bytes)


@dataclass
class ProgramRun:
    robot_id: int
    path: Path
    process: subprocess.Popen | None = None
    exit_code: int | None = None
    stopped_by_us: bool = False
    error: str | None = None
    options: ProgramOptions = ProgramOptions()
    output: dict = field(default_factory=lambda: {"stdout": [], "stderr": []})  # text as it came
    truncated: bool = False  # output beyond OUTPUT_LIMIT was dropped
    source: Path | None = None  # the C/C++ source `path` was compiled from, if it was given as one

    def text(self, stream: str = "stdout") -> str:
        return "".join(self.output[stream])

    @property
    def crash(self) -> str | None:
        """Why the program ended, in words, when a crash, a signal or a limit ended it and we did
        not stop it: 'crashed: segmentation fault (SIGSEGV)', 'crashed: access violation (0xC0000005)'."""
        return None if self.stopped_by_us else platform.exit_reason(self.exit_code)

    @property
    def name(self) -> str:
        return (self.source or self.path).name

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


def program_environment(host: str, port: int, robot_id: int, token: str | None = None) -> dict[str, str]:
    """Ours plus where the simulator is, the run's program token (EYESIM_TOKEN; none when the
    simulator wants none), and where libeyesim is for programs that load it by name
    (platform.library_environment)."""
    env = dict(os.environ, EYESIM_HOST=host, EYESIM_PORT=str(port), EYESIM_ROBOT=str(robot_id))
    env.pop("EYESIM_TOKEN", None)  # another run's
    if token is not None:
        env["EYESIM_TOKEN"] = token
    env.setdefault("PYTHONUNBUFFERED", "1")
    env.setdefault("PYTHONIOENCODING", "utf-8")  # as C programs' text: Windows would use its ANSI code page
    return platform.library_environment(env, paths.robios_lib_dir())


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
        self._waiters: dict[int, threading.Thread] = {}  # id(run) -> the thread that waits for its exit
        self._outputs: dict[int, ProgramOutput] = {}  # id(run) -> its output pipes, until it exited

    def start(self, robot_id: int, path: str | Path, options: ProgramOptions = ProgramOptions()) -> ProgramRun:
        run = ProgramRun(robot_id, sources.locate(Path(path)), options=options)
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
        run.path = run.path.resolve()
        if sources.is_source(run.path) and not self._build(run):
            return run
        env = dict(program_environment(self.host, self.port, robot_id, self.sim.program_token), **options.env)
        robot_id_ = robot_id
        self.sim.call(lambda sim: sim.expected_programs.add(robot_id_))
        try:
            process = run.process = platform.start(
                [*command_for(run.path), *options.args],
                own_group=options.own_group,
                limits=options.limits,
                cwd=options.cwd or (run.source or run.path).parent,
                env=env,
                stdin=subprocess.DEVNULL if options.stdin is None else subprocess.PIPE,
                stdout=subprocess.PIPE,
                stderr=subprocess.PIPE,
            )
        except OSError as error:
            run.error = f"cannot start {run.path}: {error.strerror}"
            self._print(run, "stderr", f"eyesim: {run.error}\n")
            self.sim.call(lambda sim: sim.program_gone(robot_id_))
            return run
        self.sim.call(lambda sim: sim.events.program(robot_id_, "started", run.name, None))
        output = ProgramOutput(
            {"stdout": process.stdout, "stderr": process.stderr}, lambda stream, text: self._show(run, stream, text)
        )
        self._outputs[id(run)] = output
        pid = process.pid

        def watch(sim):
            output.watch(sim.network)
            sim.program_outputs[pid] = output

        self.sim.on_loop(watch)
        if options.stdin is not None:
            feeder = threading.Thread(target=self._feed, args=(process, options.stdin), daemon=True)
            feeder.start()
            self._threads.append(feeder)
        waiter = threading.Thread(target=self._wait, args=(run, process), daemon=True)
        self._threads.append(waiter)
        self._waiters[id(run)] = waiter
        waiter.start()
        return run

    def _build(self, run: ProgramRun) -> bool:
        """A C/C++ source: compile it (or take it from the cache) and run the executable; its
        warnings go to the console. False, with the compiler's errors as the run's error, when it
        does not compile."""
        try:
            executable, said = sources.executable_for(run.path)
        except sources.BuildError as error:
            run.error = f"{run.path.name} does not compile:\n{error}"
            self._print(run, "stderr", f"eyesim: {run.error}\n")
            return False
        if said.strip():
            self._print(run, "stderr", said if said.endswith("\n") else said + "\n")
        run.source, run.path = run.path, executable
        return True

    def settle(self, wait: float = 0.0) -> None:
        """Let programs that are ending finish (up to `wait` s, and ENDING_GRACE for those whose
        connection has closed), then take in everything the ended ones printed and their exit codes."""
        self._let_finish(wait)
        for run in self.runs:
            if run.process is not None and run.process.poll() is not None:
                self._waiters[id(run)].join(timeout=2.0)
                self._take_output(run, run.process)

    def _let_finish(self, seconds: float) -> None:
        """Wait up to `seconds` in all for programs to end by themselves, and up to ENDING_GRACE for
        those whose connection to the simulator has closed: they are exiting, and their exit code
        is what ended them. Waited for, not polled: while the waiter thread waits for a process,
        poll() cannot tell that it has just ended."""
        start = time.monotonic()
        for run in self.runs:
            if run.process is None or run.exit_code is not None:
                continue
            closed = run.process.pid in self.sim.disconnected_pids
            remaining = start + max(seconds, ENDING_GRACE if closed else 0.0) - time.monotonic()
            if remaining > 0:
                try:
                    run.process.wait(timeout=remaining)
                except subprocess.TimeoutExpired:
                    pass

    def _feed(self, process: subprocess.Popen, data: str | bytes) -> None:
        stdin = cast(IO[bytes], process.stdin)  # a pipe: started with stdin=PIPE
        try:
            stdin.write(data.encode() if isinstance(data, str) else data)
            stdin.close()
        except OSError:
            pass  # the program ended without reading all of it

    def _take_output(self, run: ProgramRun, process: subprocess.Popen) -> None:
        """The program exited: the rest of its output, and why it ended if it crashed. On the
        simulation thread, or while no loop runs."""
        output = self._outputs.pop(id(run), None)
        if output is not None:
            output.finish()  # its last words first, then why it ended
            self.sim.program_outputs.pop(process.pid, None)
            if run.crash is not None:
                self._show(run, "stderr", f"eyesim: {run.name} {run.crash}\n")

    def _show(self, run: ProgramRun, stream: str, text: str) -> None:
        """Output read on the simulation thread (or while no loop runs): shown at this simulation time."""
        self._keep(run, stream, text)
        self.sim.events.console(run.robot_id, stream, text)

    def _print(self, run: ProgramRun, stream: str, text: str) -> None:
        """The launcher's own messages about a program, from any thread."""
        self._keep(run, stream, text)
        robot_id = run.robot_id
        self.sim.call(lambda sim: sim.events.console(robot_id, stream, text))

    def _keep(self, run: ProgramRun, stream: str, text: str) -> None:
        with self._lock:
            kept = sum(map(len, run.output[stream]))
            if kept + len(text) <= OUTPUT_LIMIT:
                run.output[stream].append(text)
            else:
                run.output[stream].append(text[: max(0, OUTPUT_LIMIT - kept)])
                run.truncated = True
        if self.echo:
            with self._lock:
                target = sys.stdout if stream == "stdout" else sys.stderr
                target.write(f"[robot {run.robot_id}] {text.rstrip(chr(10))}\n")
                target.flush()

    def _wait(self, run: ProgramRun, process: subprocess.Popen) -> None:
        run.exit_code = process.wait()
        if not run.options.own_group:
            platform.release(process)  # a group of its own is ended (and released) by _end
        robot_id = run.robot_id

        def exited(sim):
            self._take_output(run, process)
            sim.events.program(robot_id, "exited", run.name, run.exit_code)
            sim.program_gone(robot_id)

        self.sim.call(exited)

    def kill(self, run: ProgramRun) -> None:
        """Stop a program at once (a watchdog's last resort), with its process group if it has one."""
        if run.process is not None and run.process.poll() is None:
            run.stopped_by_us = True
            platform.kill_tree(run.process, run.options.own_group)

    def stop(self, run: ProgramRun, grace: float = 2.0) -> None:
        """Stop one program (the viewer's Stop button): asked to end, then killed after `grace` s.
        Blocks until it is gone; run it off the loops."""
        if run.process is None or run.process.poll() is not None:
            return
        run.stopped_by_us = True
        platform.ask_to_end(run.process)
        self._end(run.process, run.options.own_group, grace)
        self._waiters[id(run)].join(timeout=grace)

    @staticmethod
    def _end(process: subprocess.Popen, own_group: bool, grace: float) -> None:
        """Wait `grace` s for a program asked to end, then kill it; and whatever it started in its group."""
        try:
            process.wait(timeout=grace)
        except subprocess.TimeoutExpired:
            platform.kill_tree(process, own_group)
            process.wait()
        if own_group:
            platform.kill_tree(process, own_group=True)  # what it started and left running

    def latest(self, robot_id: int) -> ProgramRun | None:
        """The robot's most recent program run, if it had one."""
        return next((run for run in reversed(self.runs) if run.robot_id == robot_id), None)

    def stop_all(self, grace: float = 2.0, let_finish: float = 0.0) -> None:
        """Stop programs still running (the run is over) and wait for their output to drain.

        `let_finish`: seconds to wait first for programs that are ending by themselves (the run
        ended because they closed their connections); a program whose connection has closed gets
        ENDING_GRACE in any case, so its exit code is not lost to a run that ended meanwhile."""
        self._let_finish(let_finish)
        for run in self.runs:
            if run.process is not None and run.process.poll() is None:
                run.stopped_by_us = True
                platform.ask_to_end(run.process)
        for run in self.runs:
            if run.process is not None:
                self._end(run.process, run.options.own_group, grace)
        for thread in self._threads:
            thread.join(timeout=grace)
        for run in self.runs:  # the loop has ended: what they printed last is taken in here
            if run.process is not None:
                self._take_output(run, run.process)
