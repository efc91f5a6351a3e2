"""When a warm case runner (grade/warm.py) dies during a case, or cannot start at all, grading goes
on: the case it was running is a grader error that says so, the next case gets a new runner, and
where no runner starts every case starts a process of its own (the cold path), with a warning."""

from __future__ import annotations

import logging
import os
import signal
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from grade.test_sandbox import HONEST, SPEC, write_submission

from eyesim.grade import sandbox, warm
from eyesim.grade.grader import tasks_for
from eyesim.grade.isolation import WarmRunners
from eyesim.grade.spec import load_spec
from eyesim.grade.submissions import read_submission

# Drives on for a long case: still running when its runner is killed.
LINGERER = """#include "eyebot.h"
int main(void) { VWSetSpeed(50, 0); for (;;) OSWait(100); }
"""
DEADLINE = 120  # s for a condition on a loaded machine


def tasks(tmp_path: Path, student: str, source: str, case_time: float = 3) -> list[dict]:
    tmp_path.mkdir(exist_ok=True)
    (tmp_path / "spec.toml").write_text(SPEC.replace("time = 3", f"time = {case_time:g}"))
    write_submission(tmp_path / "class", student, source)
    return tasks_for(load_spec(tmp_path / "spec.toml"), read_submission(tmp_path / "class" / student))


def children(pid: int) -> list[int]:
    found = []
    for task in Path(f"/proc/{pid}/task").glob("*"):
        try:
            found += [int(child) for child in (task / "children").read_text().split()]
        except OSError:
            pass  # the thread or the process has ended
    return found


def descendants(pid: int) -> list[int]:
    found, todo = [], [pid]
    while todo:
        below = children(todo.pop())
        found += below
        todo += below
    return found


def command_line(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
    except OSError:
        return ""


def warm_runners() -> list[int]:
    """Our warm runners' sandboxes (the bwrap processes we started to run eyesim.grade.warm)."""
    return [
        pid
        for pid in children(os.getpid())
        if "eyesim.grade.warm" in command_line(pid) and command_line(pid).startswith(sandbox.bwrap())
    ]


def wait_for(condition, what: str):
    deadline = time.monotonic() + DEADLINE
    while not (value := condition()):
        assert time.monotonic() < deadline, f"no {what} after {DEADLINE} s"
        time.sleep(0.01)
    return value


def test_a_runner_that_dies_during_a_case_fails_that_case_and_the_next_gets_a_new_one(tmp_path):
    assert warm.usable(), "warm runners need bubblewrap and a grader running as root (as make test runs)"
    lingering = tasks(tmp_path / "a", "lingerer", LINGERER, case_time=600)[0]
    honest = tasks(tmp_path / "b", "honest", HONEST % ("honest", 250))[0]
    runners = WarmRunners()
    try:
        with ThreadPoolExecutor(1) as pool:  # one thread: one runner at a time, as a pool worker has
            running = pool.submit(runners.run, lingering)
            runner = wait_for(lambda: warm_runners()[0] if len(warm_runners()) == 1 else None, "warm runner")
            program = wait_for(  # the student's program runs: the case is under way
                lambda: next(
                    (p for p in descendants(runner) if command_line(p).split(" ")[0].endswith("/build/prog")), None
                ),
                "running program",
            )
            os.killpg(runner, signal.SIGKILL)
            died = running.result(timeout=DEADLINE)
            assert died["status"] == "grader_error"
            assert died["error"].startswith("the warm runner of the case process ended during the case")
            wait_for(lambda: not Path(f"/proc/{program}").exists(), "end of the program with its runner")

            after = pool.submit(runners.run, honest).result(timeout=DEADLINE)
            assert after["status"] == "ok" and after["score"] == 1.0, after.get("error")
            assert len(warm_runners()) == 1 and warm_runners()[0] != runner  # a new runner ran it
    finally:
        runners.close()
    assert warm_runners() == []


def test_cases_start_cold_when_no_runner_starts(tmp_path, monkeypatch, caplog):
    assert warm.usable(), "warm runners need bubblewrap and a grader running as root (as make test runs)"
    # A runner whose Python ends before it is ready, as one does where the kernel refuses it namespaces.
    monkeypatch.setattr(
        sandbox,
        "warm_command",
        lambda inner, spool: [sys.executable, "-c", "raise SystemExit('cases cannot have namespaces here')"],
    )
    honest = tasks(tmp_path, "honest", HONEST % ("honest", 250))
    runners = WarmRunners()
    try:
        with caplog.at_level(logging.WARNING, logger="eyesim"):
            results = [runners.run(task) for task in honest + honest]
    finally:
        runners.close()
    assert [(r["status"], r["score"]) for r in results] == [("ok", 1.0), ("ok", 1.0)]
    assert not runners.usable
    warnings = [r.getMessage() for r in caplog.records if r.levelno == logging.WARNING]
    assert len(warnings) == 1, warnings  # said once, not per case
    assert "the warm case runner did not start: cases cannot have namespaces here" in warnings[0]
    assert "each case starts a process of its own instead" in warnings[0]
    assert warm_runners() == []
