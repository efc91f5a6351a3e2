"""Sleeping with the C library's sleep/usleep/nanosleep/clock_nanosleep and Python's time.sleep:
once connected, the pause is simulation time, exactly as OSWait (deterministic runs give the same
time and the same pose); before the first RoBIOS call it is the system's sleep in wall time."""

import os
import re
import textwrap

import pytest
from support.programs import build, run_headless

from eyesim.core.engine import DEFAULT_CALL_TIME_US

CALL_MS = DEFAULT_CALL_TIME_US // 1000
CALLS = 4 * 2  # two MOTORDrive per phase (the clock reads are local: 10 us, within their millisecond)


def run_phases(program, tmp_path, kind: str, ms: int, *args: str):
    env = dict(os.environ, SLEEP_KIND=kind, SLEEP_MS=str(ms))
    result = run_headless(*args, "--program", f"1={program}", cwd=tmp_path, env=env)
    assert result.returncode == 0, result.stdout + result.stderr
    slept = int(re.search(r"\[robot 1\] slept (\d+) ms", result.stdout).group(1))
    pose = re.search(r"robot 1 S4: (x=.*deg)", result.stdout).group(1)
    wall_before = float(re.search(r"wall before connecting (\d+) ms", result.stdout).group(1))
    return slept, pose, wall_before


@pytest.fixture(scope="module")
def phases(tmp_path_factory):
    out = tmp_path_factory.mktemp("sleep")
    return build("sleep_phases", out, "-Wall", "-Wextra", "-Werror"), out


@pytest.mark.parametrize("kind,ms", [("usleep", 500), ("nanosleep", 500), ("clock_nanosleep", 500), ("sleep", 1000)])
def test_sleeps_wait_in_simulation_time_like_os_wait(phases, kind, ms):
    program, out = phases
    slept, pose, wall_before = run_phases(program, out, kind, ms)
    assert slept == 4 * ms + CALLS * CALL_MS  # four pauses and the calls' own time, exactly
    reference = run_phases(program, out, "OSWait", ms)
    assert (slept, pose) == reference[:2]  # the same run, bit for bit, as with OSWait
    x = int(re.match(r"x=(\d+) mm", pose).group(1))
    assert x - 500 > 150 * ms / 500  # it drove during the two forward phases
    assert wall_before >= 100  # the usleep before connecting was a real one


def test_realtime_sleeps_follow_simulation_time_at_the_speed_factor(phases):
    program, out = phases
    slept, _, _ = run_phases(program, out, "usleep", 500, "--clock", "realtime", "--speed", "4")
    assert 4 * 500 + CALLS * CALL_MS <= slept < 4 * 500 + 400  # not 4 x 500 ms of wall time x 4


PYTHON = """
    import time
    from eye import *

    before = time.monotonic()
    time.sleep(0.1)                          # not connected yet: wall time
    print("wall before connecting", round((time.monotonic() - before) * 1000), flush=True)
    start = OSGetCount()
    for phase in range(4):
        speed = 40 if phase % 2 == 0 else 0
        MOTORDrive(1, speed)
        MOTORDrive(2, speed)
        time.sleep(0.5)
    print("slept", OSGetCount() - start, flush=True)
    x, y, z, phi = SIMGetRobot(0)
    print("x", x.value if hasattr(x, "value") else x, flush=True)
"""


def test_python_time_sleep_waits_in_simulation_time(tmp_path):
    program = tmp_path / "phases.py"
    program.write_text(textwrap.dedent(PYTHON))
    result = run_headless("--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    out = result.stdout
    assert int(re.search(r"\[robot 1\] slept (\d+)", out).group(1)) == 2000 + CALLS * CALL_MS
    assert int(re.search(r"\[robot 1\] wall before connecting (\d+)", out).group(1)) >= 100
    assert int(re.search(r"\[robot 1\] x (\d+)", out).group(1)) > 650
