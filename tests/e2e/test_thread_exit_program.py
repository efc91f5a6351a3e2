"""A C program whose main ends with pthread_exit after starting worker threads (as the official
multitasking examples do) ends when its workers end: the library's reader and timer threads do not
keep it alive, the simulator sees it go and a headless run ends, in both clock modes."""

import re

import pytest
from support.programs import build, run_headless


@pytest.mark.parametrize("clock", ["deterministic", "realtime"])
def test_program_ends_with_its_worker_threads(tmp_path, clock):
    program = build("thread_exit", tmp_path, "-Wall", "-Wextra", "-Werror")
    # No --until: the run ends only if the program's process ends (a hang hits the timeout).
    result = run_headless("--clock", clock, "--program", f"1={program}", cwd=tmp_path, timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    out = result.stdout
    assert "program thread_exit: exit code 0" in out
    for line in ("round 1", "round 2", "round 3", "drive done"):  # stdout flushed at the end
        assert f"[robot 1] {line}\n" in out
    ticks = int(re.search(r"timer ticks (\d+)", out).group(1))
    # 100 ms timer over the reporter's 600 ms; two threads calling at once are not lock-step
    # reproducible (docs/running.md), so their turns, and the count, vary a little with the load
    assert 5 <= ticks <= 9
    x = float(re.search(r"robot 1 S4: x=(\d+) mm", out).group(1))
    assert 790 <= x <= 810  # started at 500, drove 300 mm
    stopped = float(re.search(r"stopped at t=([\d.]+) s", out).group(1))
    assert stopped < 3.0  # ended with the drive (about 1.4 s), not at some time limit
