"""Running one case in a process of its own, wherever this function is called: in a thread of
the local pool or in a Dask worker. The case process has its own port, its own temporary
directory and its own process group (a job on Windows); when it overruns its case's wall-clock limit by
HARD_MARGIN it is killed with everything in its group, and the case is reported, not lost."""

from __future__ import annotations

import pickle
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from eyesim import platform

HARD_MARGIN = 60.0  # s beyond the case's own watchdog (which stops programs gently) before killing

_running: set[subprocess.Popen] = set()  # case processes of this process, for an interrupted run
_running_lock = threading.Lock()


def kill_running() -> None:
    """Kill every case process this process started that is still running (Ctrl-C)."""
    with _running_lock:
        processes = list(_running)
    for process in processes:
        platform.kill_tree(process, own_group=True)


def failed_result(task: dict, status: str, message: str) -> dict:
    from eyesim.grade.case_run import _not_run

    case = task["case"]
    return {"student": task["student"], "case": case.name, "weight": case.weight, "key": task["key"],
            "status": status, "score": 0.0, "checks": _not_run(case, message), "error": message, "artifacts": {}}


def run_case_isolated(task: dict) -> dict:
    """Grade one submission x case in a fresh `python -m eyesim.grade.case_run`; returns its result."""
    started = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="eyesim-grade-") as tmp:
        result_path = Path(tmp) / "result.pickle"
        process = platform.start([sys.executable, "-m", "eyesim.grade.case_run", str(result_path),
                                  str(Path(tmp) / "case")], own_group=True,
                                 stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd=tmp)
        with _running_lock:
            _running.add(process)
        try:
            _, stderr = process.communicate(pickle.dumps(task), timeout=task["case"].wall_clock + HARD_MARGIN)
        except subprocess.TimeoutExpired:
            _kill_group(process)
            return dict(failed_result(task, "timeout", f"the case took over {task['case'].wall_clock + HARD_MARGIN:g} s "
                                                         f"of real time and was killed"),
                        timing={"case_seconds": round(time.perf_counter() - started, 3)})
        finally:
            _kill_group(process)  # programs the case left behind in its group
            with _running_lock:
                _running.discard(process)
        if not result_path.exists():
            tail = stderr.decode(errors="replace")[-3000:]
            return dict(failed_result(task, "grader_error", f"the case process ended with status {process.returncode} "
                                                              f"without a result:\n{tail}"),
                        timing={"case_seconds": round(time.perf_counter() - started, 3)})
        return pickle.loads(result_path.read_bytes())


def _kill_group(process: subprocess.Popen) -> None:
    platform.kill_tree(process, own_group=True)
    process.wait()
