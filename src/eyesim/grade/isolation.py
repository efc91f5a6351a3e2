"""Running one case in a process of its own, wherever this function is called: in a thread of
the local pool or in a Dask worker. The case process has its own port, its own temporary
directory and its own process group (a job on Windows), and on Linux with bubblewrap a sandbox of
its own (sandbox.py), or namespaces of its own when a warm runner forked it (warm.py); when it
overruns its case's wall-clock limit by HARD_MARGIN it is killed with everything in it (a warm
runner with it), and the case is reported, not lost.

The case process answers with JSON on its standard output, never with a file in its work folder
(which the submission could rewrite) nor with a pickle (which would run code in the grader). What
the grader knows itself (student, case, weight, key) it does not take from the answer."""

from __future__ import annotations

import base64
import contextlib
import json
import logging
import os
import pickle
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Protocol

from eyesim import platform
from eyesim.grade import sandbox, warm

HARD_MARGIN = 60.0  # s beyond the case's own watchdog (which stops programs gently) before killing
CASE_PROCESSES = 256  # processes and threads a sandboxed case's user may have (simulator threads included)

log = logging.getLogger("eyesim")
_running: set[subprocess.Popen] = set()  # case processes of this process, for an interrupted run
_running_lock = threading.Lock()


class RunningCase(Protocol):
    """A case process as the grader talks to it: a cold one (subprocess.Popen) or one a warm
    runner forked (warm.CaseProcess)."""

    @property
    def returncode(self) -> int | None: ...

    def communicate(self, input: bytes, timeout: float, /) -> tuple[bytes, bytes]: ...


def kill_running() -> None:
    """Kill every case process this process started that is still running (Ctrl-C)."""
    with _running_lock:
        processes = list(_running)
    for process in processes:
        platform.kill_tree(process, own_group=True)


def failed_result(task: dict, status: str, message: str) -> dict:
    from eyesim.grade.case_run import _not_run

    case = task["case"]
    return {
        "student": task["student"],
        "case": case.name,
        "weight": case.weight,
        "key": task["key"],
        "status": status,
        "score": 0.0,
        "checks": _not_run(case, message),
        "error": message,
        "artifacts": {},
    }


def run_case_isolated(task: dict, runner: warm.Runner | None = None) -> dict:
    """Grade one submission x case in a fresh `python -m eyesim.grade.case_run`, or in a fresh
    process forked by the warm `runner` (warm.py) when the case is to be sandboxed; returns its result."""
    started = time.perf_counter()

    def timed(result: dict) -> dict:
        return dict(result, timing={"case_seconds": round(time.perf_counter() - started, 3)})

    unisolated = sandbox.why_not_isolated()
    if unisolated and task.get("require_isolation"):
        return timed(failed_result(task, "grader_error", f"refused: {unisolated} (--require-isolation)"))
    process: RunningCase
    with contextlib.ExitStack() as stack:
        if runner is not None and task.get("isolate", True):
            uid = sandbox.case_uid()
            assert uid is not None, "warm runners run only for a root grader (warm.usable), which has case users"
            folder, process = runner.start_case(uid)
            task, watched = dict(task, processes=CASE_PROCESSES), runner.process
        else:
            folder = None
            watched, task = _start_case(
                task, Path(stack.enter_context(tempfile.TemporaryDirectory(prefix="eyesim-grade-")))
            )
            process = watched
        with _running_lock:
            _running.add(watched)
        timeout = task["case"].wall_clock + HARD_MARGIN
        try:
            stdout, stderr = process.communicate(pickle.dumps(task), timeout)
        except subprocess.TimeoutExpired:
            _kill_group(watched)
            return timed(
                failed_result(task, "timeout", f"the case took over {timeout:g} s of real time and was killed")
            )
        finally:
            if folder is None:
                _kill_group(watched)  # the case process, and programs the case left behind in its group
            else:
                shutil.rmtree(folder, ignore_errors=True)  # its namespaces ended with it
            with _running_lock:
                _running.discard(watched)
        result = _read_result(stdout, task)
        if result is None:
            tail = stderr.decode(errors="replace")[-3000:]
            ended = (
                "the warm runner of the case process ended during the case"
                if process.returncode is None
                else f"the case process ended with status {process.returncode}"
            )
            return timed(failed_result(task, "grader_error", f"{ended} without a result:\n{tail}"))
        return result


class WarmRunners:
    """A warm runner (warm.py) for each thread that runs cases, made for its first case and made
    again when a case had to end it. Where runners cannot be used, or one does not start, cases
    start cold, each in a sandbox of its own. Used by the local pool and by each Dask worker."""

    def __init__(self):
        self.usable = warm.usable()
        self._local = threading.local()
        self._runners: list[warm.Runner] = []
        self._lock = threading.Lock()

    def run(self, task: dict) -> dict:
        if not self.usable:
            return run_case_isolated(task)
        try:
            runner = getattr(self._local, "runner", None)
            if runner is None or runner.process.poll() is not None:  # the first case, or a case overran
                runner = self._local.runner = warm.Runner()
                with self._lock:
                    self._runners.append(runner)
            return run_case_isolated(task, runner)
        except warm.RunnerFailed as error:
            if self.usable:
                log.warning("%s; each case starts a process of its own instead", error)
            self.usable = False  # the cases start cold, each in a bwrap sandbox of its own
            return run_case_isolated(task)

    def close(self) -> None:
        with self._lock:
            runners, self._runners = self._runners, []
        for runner in runners:
            runner.close()


def _start_case(task: dict, work: Path) -> tuple[subprocess.Popen, dict]:
    """The case process, sandboxed where bubblewrap is (and the task allows), with the task as it
    is sent to it."""
    command = [sys.executable, "-m", "eyesim.grade.case_run", str(work / "case")]
    if task.get("isolate", True) and sandbox.bwrap() is not None:
        uid = sandbox.case_uid()
        if uid is not None:
            os.chown(work, uid, uid)
        task = dict(task, processes=CASE_PROCESSES if uid is not None else None)
        command = sandbox.command(command, work, uid)
    process = platform.start(
        command, own_group=True, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=work
    )
    return process, task


def _read_result(stdout: bytes, task: dict) -> dict | None:
    """The case process's answer, checked for its shape; None when there is none."""
    try:
        result = json.loads(stdout)
        if not isinstance(result, dict) or not isinstance(result.get("checks"), list):
            return None
        score = float(result["score"])
        artifacts = {
            str(name): base64.b64decode(data)
            for name, data in (result.get("artifacts") or {}).items()
            if "/" not in str(name) and not str(name).startswith(".")
        }
    except (ValueError, TypeError, KeyError, AttributeError):
        return None
    case = task["case"]
    return dict(
        result,
        student=task["student"],
        case=case.name,
        weight=case.weight,
        key=task["key"],
        score=min(1.0, max(0.0, score)),
        artifacts=artifacts,
    )


def _kill_group(process: subprocess.Popen) -> None:
    platform.kill_tree(process, own_group=True)
    process.wait()
