"""Running the Windows EyeSim under Wine from Linux tests: its commands, its programs (Python, and C
cross-compiled with Zig against the wheel's eyebot.h and eyesim.dll), and the Windows processes
they leave (every Windows process under Wine is a Linux process whose command line is the Windows
one, so /proc shows them)."""

from __future__ import annotations

import contextlib
import os
import re
import signal
import socket
import subprocess
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path

from support.cross import TARGETS, zig_cc
from windows_env import WindowsEnv, windows_path

WINDOWS_TARGET = TARGETS["windows-x86_64"]
HERE = Path(__file__).resolve().parent
PROGRAMS = HERE / "programs"


def wait_until(condition: Callable[[], object], timeout: float, what: str, interval: float = 0.05):
    """Polls `condition` until it returns something true (returned), failing after `timeout` s."""
    deadline = time.monotonic() + timeout
    while True:
        value = condition()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(interval)


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def processes_mentioning(token: str) -> dict[int, str]:
    """pid -> command line of every process whose command line contains `token` (Windows processes
    under Wine show their Windows command line)."""
    found = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit() or int(entry.name) == os.getpid():
            continue
        try:
            command = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace").strip()
        except OSError:
            continue
        if token in command:
            found[int(entry.name)] = command
    return found


def kill_processes(pids) -> None:
    for pid in pids:
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.kill(pid, signal.SIGKILL)


@dataclass
class WindowsEyeSim:
    env: WindowsEnv

    def command(self, *args: str) -> list[str]:
        """`eyesim ARGS` with the Windows Python (-P: the working directory, which holds the test's
        programs, is not put on sys.path)."""
        return self.env.command("-P", "-m", "eyesim", *args)

    def run(
        self, *args: str, cwd: Path, timeout: float = 180, env: dict[str, str] | None = None, text: bool = True
    ) -> subprocess.CompletedProcess:
        """`eyesim ARGS` under Wine to its end; its output as text (UTF-8, errors replaced) or, with
        `text=False`, bytes. Its standard handles are pipes and NUL: Wine 8 gives python.exe an
        invalid handle for a regular file as stdin/stdout/stderr, and it cannot start."""
        try:
            return subprocess.run(
                self.command(*args),
                cwd=cwd,
                env=env or self.env.environment(),
                stdin=subprocess.DEVNULL,
                capture_output=True,
                text=text,
                errors="replace" if text else None,
                timeout=timeout,
            )
        except subprocess.TimeoutExpired as expired:
            output = b"".join(part or b"" for part in (expired.stdout, expired.stderr)).decode(errors="replace")
            raise AssertionError(
                f"`eyesim {' '.join(args)}` did not end within {timeout} s; its output:\n{output}"
            ) from None

    def start(self, *args: str, cwd: Path, env: dict[str, str] | None = None) -> subprocess.Popen:
        """`eyesim ARGS` under Wine, running; stdout and stderr merged into one text pipe."""
        return subprocess.Popen(
            self.command(*args),
            cwd=cwd,
            env=env or self.env.environment(),
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            errors="replace",
        )

    @property
    def robios_include(self) -> Path:
        return self.env.robios / "include"

    @property
    def robios_lib(self) -> Path:
        return self.env.robios / "lib"

    def compile_c(self, source: Path, output: Path, *flags: str, with_eyesim: bool = True) -> Path:
        """A Windows .exe from C, built on Linux with Zig (zig.exe does not run under Wine 8, so
        `eyesim cc` cannot be used there) against the installed wheel's eyebot.h and eyesim.dll."""
        args = [*flags, str(source), "-o", str(output)]
        if with_eyesim:
            args = ["-I", str(self.robios_include), *args, "-L", str(self.robios_lib), "-leyesim"]
        result = zig_cc(WINDOWS_TARGET, *args, cwd=output.parent)
        assert result.returncode == 0, f"zig cc for Windows failed:\n{result.stdout}{result.stderr}"
        output.with_suffix(".pdb").unlink(missing_ok=True)
        return output

    @staticmethod
    def path(path: Path) -> str:
        return windows_path(path)


@contextlib.contextmanager
def no_process_left(token: str, grace: float = 20) -> Iterator[None]:
    """Fails when, `grace` s after the block, a process whose command line holds `token` is still
    running (and kills those, so one failure does not leak into the next test)."""
    try:
        yield
    except BaseException:
        kill_processes(processes_mentioning(token))  # the test failed already: just clean up
        raise
    try:
        wait_until(lambda: not processes_mentioning(token), grace, f"the processes of {token} to end")
    except AssertionError:
        left = processes_mentioning(token)
        kill_processes(left)
        raise AssertionError(f"processes left running after the run: {left}") from None


class OutputReader:
    """Collects a running process's output lines on a thread, so tests can wait for a line without
    blocking on the pipe."""

    def __init__(self, process: subprocess.Popen):
        self.lines: list[str] = []
        self._thread = threading.Thread(target=self._read, args=(process.stdout,), daemon=True)
        self._thread.start()

    def _read(self, pipe) -> None:
        for line in pipe:
            self.lines.append(line)

    def text(self) -> str:
        return "".join(self.lines)

    def finish(self, timeout: float = 30) -> str:
        """All the output, once the process has ended it."""
        self._thread.join(timeout)
        assert not self._thread.is_alive(), f"the output did not end within {timeout} s:\n{self.text()}"
        return self.text()

    def wait_for(self, pattern: str, timeout: float) -> re.Match:
        """The first match of `pattern` in the output, waiting up to `timeout` s; fails with the output
        so far (at once when the output has ended without it)."""
        deadline = time.monotonic() + timeout
        while True:
            ended = not self._thread.is_alive()
            match = re.search(pattern, self.text())
            if match:
                return match
            if ended:
                raise AssertionError(f"the output ended without {pattern!r}:\n{self.text()}")
            if time.monotonic() > deadline:
                raise AssertionError(f"no {pattern!r} in the output within {timeout} s:\n{self.text()}")
            time.sleep(0.05)
