"""A second thread waiting in KEYGet must not slow or reorder the main thread's control loop: in a
deterministic run, time goes on only while every calling thread waits, so the loop turns as far
as it does alone (it turned 7-18 degrees, varying from run to run, where alone it turns 34). When
the second thread starts is still the operating system's choice, which the run warns about: the
loop's first call or two may come before the simulator has seen both threads."""

from __future__ import annotations

import re

from support.programs import build, run_headless


def turned(result) -> int:
    assert result.returncode == 0, result.stdout + result.stderr
    found = re.search(r"turned (-?\d+)", result.stdout)
    assert found, result.stdout + result.stderr
    return int(found.group(1))


def test_a_thread_waiting_for_a_key_leaves_the_control_loop_as_it_is_alone(tmp_path):
    program = build("key_thread_vw_loop", tmp_path)
    alone = tmp_path / "alone.sh"
    alone.write_text(f"#!/bin/sh\nexec {program} alone\n")
    alone.chmod(0o755)
    single = turned(run_headless("--program", f"1={alone}", "--until", "3", cwd=tmp_path))
    runs = [turned(run_headless("--program", f"1={program}", "--until", "3", cwd=tmp_path)) for _ in range(3)]
    assert 34 <= single <= 40
    assert all(abs(run - single) <= 2 for run in runs), (single, runs)
