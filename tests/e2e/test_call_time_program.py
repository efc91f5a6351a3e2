"""The per-call time from a real C program: every ordinary call takes the call time of simulation
time (default, scene CALLTIME=, --call-time), so a loop that counts iterations instead of time gets
the number the call time implies (deterministic) and 100 calls take at least 100 call times
(realtime, where the simulator holds each reply back)."""

import re

import pytest
from support.programs import build, run_headless

from eyesim.core.engine import DEFAULT_CALL_TIME_US
from eyesim.paths import DATA_DIR


def counted(output: str) -> tuple[int, int]:
    iterations = int(re.search(r"\[robot 1\] iterations (\d+)", output).group(1))
    took = int(re.search(r"\[robot 1\] 100 calls took (\d+) ms", output).group(1))
    return iterations, took


def scene_with(tmp_path, settings: str):
    scene = tmp_path / "calls.sim"
    scene.write_text(f"world {DATA_DIR / 'scenes' / 'arena.wld'}\nsettings {settings}\nS4 500 500 0\n")
    return scene


@pytest.mark.parametrize("how,call_ms", [("default", DEFAULT_CALL_TIME_US / 1000), ("flag", 2), ("scene", 1),
                                         ("flag over scene", 5)])
def test_deterministic_loop_iterations_follow_the_call_time(tmp_path, how, call_ms):
    program = build("count_calls", tmp_path, "-Wall", "-Wextra", "-Werror")
    args = {"default": [], "flag": ["--call-time", "2"], "scene": [str(scene_with(tmp_path, "CALLTIME=1"))],
            "flag over scene": [str(scene_with(tmp_path, "CALLTIME=1")), "--call-time", "5"]}[how]
    result = run_headless(*args, "--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    iterations, took = counted(result.stdout)
    assert iterations == 1000 / (2 * call_ms)  # two calls per iteration
    assert took == 100 * call_ms + call_ms  # 100 calls and the first OSGetCount's own time


def test_a_call_time_of_0_gives_the_protocols_own_costs(tmp_path):
    program = build("count_calls", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--call-time", "0", "--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert counted(result.stdout) == (5000, 10)  # 0.1 ms per call


def test_realtime_replies_wait_for_the_call_time(tmp_path):
    program = build("count_calls", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--clock", "realtime", "--speed", "4", "--call-time", "4", "--program", f"1={program}",
                          cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    iterations, took = counted(result.stdout)
    # At most what 8 ms of simulation time per iteration allow; fewer as each round trip adds its own.
    assert 30 <= iterations <= 125
    assert took >= 100 * 4 + 4  # never less; more when the machine is slow
    stopped = float(re.search(r"stopped at t=([\d.]+) s", result.stdout).group(1))
    assert stopped >= 1.4
