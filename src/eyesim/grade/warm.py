"""Warm case runners (Linux, bubblewrap, the grader running as root): a case process without the
start of a Python and the import of the simulator (about 0.3-0.5 s of CPU per case).

A runner is a Python process in a bwrap sandbox (sandbox.warm_command) that has imported what a
case needs and then, for each case it is sent, forks. The fork enters new namespaces
(sandbox.enter_case_namespaces) and forks the case's init, which sets up the case's file system
(sandbox.case_file_system: its own /proc, only its own folder) and forks the case process, which
becomes the case's own user and runs case_run.main. When the case process ends, its init ends and
the kernel kills everything left in its namespaces, as when bwrap's sandbox ends. Nothing of one
case is in the runner: it never reads a task, it only forks. Each case gets what `sandbox.command`
gives it: namespaces, file system, user, limits and answer by its standard output alike.

The grader sends the runner the case's folder name and its user, with the case process's stdin,
stdout and stderr as file descriptors over a Unix socket; the runner answers with the case
process's exit status when it has ended. One case at a time per runner; a case that overruns is
ended with its runner, and the next case starts a new runner.

    python -m eyesim.grade.warm SPOOL     (its standard input is the Unix socket)
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from eyesim.grade import sandbox

# What case_run imports while running a case, imported once by the runner.
CASE_MODULES = (
    "eyesim.grade.case_run",
    "eyesim.grade.checks",
    "eyesim.testing",
    "eyesim.testing.assertions",
    "eyesim.record",
    "eyesim.core.stalls",
    "eyesim.programs.toolchain",
    "PIL.Image",
    "PIL.PngImagePlugin",
)
MESSAGE = 4096  # bytes, at most, of a request or an answer
READY_TIMEOUT = 120  # s for a runner's imports and its first namespaces on a loaded machine


class RunnerFailed(Exception):
    """A runner could not start, or cannot give cases namespaces here: cases start cold instead."""


def usable() -> bool:
    """Whether cases can run in warm runners here: sandboxed by bwrap, and the grader is root, so
    that a runner can give each case namespaces of its own."""
    return sandbox.bwrap() is not None and os.geteuid() == 0


class Runner:
    """The grader's end of one warm runner; used by one thread at a time. RunnerFailed when it
    does not say that it is ready."""

    def __init__(self):
        self.spool = Path(tempfile.mkdtemp(prefix="eyesim-warm-"))
        self._socket, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
        with theirs:
            inner = [sys.executable, "-m", "eyesim.grade.warm", str(self.spool)]
            with open(self.spool / "runner.log", "wb") as log:  # hidden from the cases with the spool
                self.process = subprocess.Popen(
                    sandbox.warm_command(inner, self.spool),
                    stdin=theirs.fileno(),
                    stdout=subprocess.DEVNULL,
                    stderr=log,
                    start_new_session=True,
                )
        self._cases = 0
        self._socket.settimeout(READY_TIMEOUT)
        try:
            ready = self._socket.recv(MESSAGE) == b"ready"
        except OSError:
            ready = False
        self._socket.settimeout(None)
        if not ready:
            said = (self.spool / "runner.log").read_text(errors="replace")[-2000:]
            self.close()
            raise RunnerFailed(f"the warm case runner did not start: {said}")

    def start_case(self, uid: int) -> tuple[Path, CaseProcess]:
        """A case process in a folder of its own (which it owns), running as `uid`."""
        self._cases += 1
        folder = self.spool / f"case{self._cases}"
        folder.mkdir(mode=0o700)
        os.chown(folder, uid, uid)
        case = CaseProcess(self)
        ends = case.child_ends()
        try:
            request = json.dumps({"folder": folder.name, "uid": uid}).encode()
            socket.send_fds(self._socket, [request], ends)
        except OSError as error:
            raise RunnerFailed(f"the warm case runner has ended: {error}") from None
        finally:
            for fd in ends:
                os.close(fd)
        return folder, case

    def exit_status(self) -> int | None:
        """The last case process's exit status, once it has ended (None when the runner is gone)."""
        try:
            answer = self._socket.recv(MESSAGE)
            return int(json.loads(answer)["status"]) if answer else None
        except (OSError, ValueError, KeyError, TypeError):
            return None

    def kill(self) -> None:
        """End the runner and every case in its sandbox."""
        try:
            os.killpg(self.process.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
        self.process.wait()
        self._socket.close()

    def close(self) -> None:
        self.kill()
        shutil.rmtree(self.spool, ignore_errors=True)


class CaseProcess:
    """Pipes to a case process a runner forked, with Popen's communicate() and returncode."""

    def __init__(self, runner: Runner):
        self._runner = runner
        self._stdin = os.pipe()
        self._stdout = os.pipe()
        self._stderr = os.pipe()
        self.returncode: int | None = None

    def child_ends(self) -> list[int]:
        return [self._stdin[0], self._stdout[1], self._stderr[1]]

    def communicate(self, data: bytes, timeout: float) -> tuple[bytes, bytes]:
        """Send `data`, read both outputs to their end; subprocess.TimeoutExpired after `timeout` s."""
        stdin, stdout, stderr = (
            os.fdopen(self._stdin[1], "wb"),
            os.fdopen(self._stdout[0], "rb"),
            os.fdopen(self._stderr[0], "rb"),
        )
        outputs: dict[str, bytes] = {}
        readers = [
            threading.Thread(target=lambda name=name, stream=stream: outputs.update({name: stream.read()}), daemon=True)
            for name, stream in (("stdout", stdout), ("stderr", stderr))
        ]
        for reader in readers:
            reader.start()
        try:
            with stdin:
                stdin.write(data)
        except BrokenPipeError:
            pass
        deadline = time.monotonic() + timeout
        for reader in readers:
            reader.join(max(0.0, deadline - time.monotonic()))
            if reader.is_alive():
                self._runner.kill()  # the pipes close with it
                raise subprocess.TimeoutExpired("warm case", timeout)
        stdout.close()
        stderr.close()
        self.returncode = self._runner.exit_status()
        return outputs["stdout"], outputs["stderr"]


# ---- The runner, in its sandbox -------------------------------------------------------------------


def serve(spool: Path) -> None:
    import importlib

    for module in CASE_MODULES:
        importlib.import_module(module)
    if threading.active_count() != 1:  # fork copies one thread: the others' locks would stay taken
        raise SystemExit("eyesim.grade.warm: an import started a thread; cannot fork cases")
    control = socket.socket(fileno=0)
    _check_namespaces(spool)
    control.sendall(b"ready")
    while True:
        try:
            request, fds, _, _ = socket.recv_fds(control, MESSAGE, 3)
        except OSError:
            return
        if not request:
            return  # the grader closed its end
        order = json.loads(request)
        child = os.fork()
        if child == 0:
            _case_child(control, spool, spool / Path(order["folder"]).name, int(order["uid"]), fds)
        for fd in fds:
            os.close(fd)
        _, status = os.waitpid(child, 0)
        control.sendall(json.dumps({"status": os.waitstatus_to_exitcode(status)}).encode())


def _check_namespaces(spool: Path) -> None:
    """Give a case's namespaces and file system to a child that does nothing else, so that a kernel
    that refuses them refuses the runner (the grader then starts each case cold), not every case."""
    folder = spool / "check"
    folder.mkdir()
    child = os.fork()
    if child == 0:
        status = 1
        try:
            sandbox.enter_case_namespaces()
            init = os.fork()
            if init == 0:
                alone = False
                try:
                    sandbox.case_file_system(spool, folder)
                    alone = os.listdir(spool) == [folder.name]
                finally:
                    os._exit(0 if alone else 1)
            status = 0 if os.waitpid(init, 0)[1] == 0 else 1
        finally:
            os._exit(status)
    status = os.waitstatus_to_exitcode(os.waitpid(child, 0)[1])
    folder.rmdir()
    if status != 0:
        raise SystemExit(f"eyesim.grade.warm: cases cannot have namespaces of their own here (status {status})")


def _case_child(control: socket.socket, spool: Path, folder: Path, uid: int, fds: list[int]) -> None:
    """Forked by the runner: enters the case's namespaces, forks its init and waits for it."""
    status = 70
    try:
        control.close()
        sandbox.enter_case_namespaces()
        init = os.fork()
        if init == 0:
            _case_init(spool, folder, uid, fds)
        for fd in fds:
            os.close(fd)
        status = os.waitstatus_to_exitcode(os.waitpid(init, 0)[1])
    except BaseException as error:  # noqa: BLE001 - the status says it failed; stderr says why
        _say(fds, f"warm runner: the case could not start: {error}")
    finally:
        os._exit(status if status >= 0 else 128 - status)


def _case_init(spool: Path, folder: Path, uid: int, fds: list[int]) -> None:
    """PID 1 of the case's namespaces: its file system, then the case process, reaping everything
    until that has ended; when this process ends, the kernel kills what is left."""
    import ctypes
    import signal

    status = 70
    try:
        ctypes.CDLL(None).prctl(1, signal.SIGKILL, 0, 0, 0)  # PR_SET_PDEATHSIG: as bwrap --die-with-parent
        sandbox.case_file_system(spool, folder)
        case = os.fork()
        if case == 0:
            _case_process(folder, uid, fds)
        for fd in fds:
            os.close(fd)
        while True:
            pid, wait_status = os.wait()
            if pid == case:
                status = os.waitstatus_to_exitcode(wait_status)
                break
    except BaseException as error:  # noqa: BLE001
        _say(fds, f"warm runner: the case could not start: {error}")
    finally:
        os._exit(status if status >= 0 else 128 - status)


def _case_process(folder: Path, uid: int, fds: list[int]) -> None:
    status = 70
    try:
        for target, fd in enumerate(fds):
            os.dup2(fd, target)
        os.closerange(3, os.sysconf("SC_OPEN_MAX"))
        os.setsid()  # as bwrap --new-session
        os.chdir(folder)
        os.environ.update(HOME=str(folder), TMPDIR=str(folder), MPLCONFIGDIR=str(folder / ".matplotlib"))
        os.environ[sandbox.CASE_UID_VARIABLE] = str(uid)
        from eyesim.grade import case_run

        status = case_run.main([str(folder / "case")])
    except BaseException as error:  # noqa: BLE001
        _say([0, 1, 2], f"warm runner: the case failed: {error}")
    finally:
        sys.stdout.flush()
        os._exit(status)


def _say(fds: list[int], text: str) -> None:
    try:
        os.write(fds[2], text.encode() + b"\n")
    except OSError:
        pass


if __name__ == "__main__":
    serve(Path(sys.argv[1]))
