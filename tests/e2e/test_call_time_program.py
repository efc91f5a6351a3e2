"""The per-call time from a real C program: every call that reaches the robot (KEYRead here) takes
the call time of simulation time (default, scene CALLTIME=, --call-time), so a loop that counts
iterations instead of time gets the number the call time implies (deterministic) and 100 calls take
at least 100 call times (realtime, where the simulator holds each reply back). Reading the clock is
local: 10 us, and never the same millisecond twice in a row (docs/protocol.md#what-a-call-costs)."""

import re

import pytest
from support.programs import build, run_headless

from eyesim.core.engine import DEFAULT_CALL_TIME_US
from eyesim.paths import DATA_DIR
from eyesim.protocol import generated as g


CLOCK_US = g.OPS_BY_NAME["OS_GET_COUNT"].cost_us


def expected_counts(call_us: int) -> tuple[int, int]:
    """What count_calls.c prints by the documented costs: a clock read costs CLOCK_US and shows a
    later millisecond than the read before it (waiting for it if need be), a KEYRead `call_us`."""
    t = last = -1

    def read():
        nonlocal t, last
        t = max(t, 0)
        ms = t // 1000
        if ms <= last:
            ms, t = last + 1, (last + 1) * 1000
        last = ms
        t += CLOCK_US
        return ms

    start, iterations = read(), 0
    while read() - start < 1000:
        t += call_us
        iterations += 1
    start = read()
    t += 100 * call_us
    return iterations, read() - start


def counted(output: str) -> tuple[int, int]:
    iterations = int(re.search(r"\[robot 1\] iterations (\d+)", output).group(1))
    took = int(re.search(r"\[robot 1\] 100 calls took (\d+) ms", output).group(1))
    return iterations, took


def scene_with(tmp_path, settings: str):
    scene = tmp_path / "calls.sim"
    scene.write_text(f"world {DATA_DIR / 'scenes' / 'arena.wld'}\nsettings {settings}\nS4 500 500 0\n")
    return scene


@pytest.mark.parametrize(
    "how,call_ms", [("default", DEFAULT_CALL_TIME_US / 1000), ("flag", 2), ("scene", 1), ("flag over scene", 5)]
)
def test_deterministic_loop_iterations_follow_the_call_time(tmp_path, how, call_ms):
    program = build("count_calls", tmp_path, "-Wall", "-Wextra", "-Werror")
    args = {
        "default": [],
        "flag": ["--call-time", "2"],
        "scene": [str(scene_with(tmp_path, "CALLTIME=1"))],
        "flag over scene": [str(scene_with(tmp_path, "CALLTIME=1")), "--call-time", "5"],
    }[how]
    result = run_headless(*args, "--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    iterations, took = counted(result.stdout)
    assert (iterations, took) == expected_counts(round(call_ms * 1000))
    assert 1000 / call_ms - 10 <= iterations <= 1000 / call_ms  # about one KEYRead's time each
    assert took == 100 * call_ms


def test_a_call_time_of_0_gives_the_protocols_own_costs(tmp_path):
    program = build("count_calls", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--call-time", "0", "--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    # 0.1 ms per KEYRead; the clock read after it, still in the same millisecond, waits for the next
    assert counted(result.stdout) == expected_counts(g.OPS_BY_NAME["KEY_READ"].cost_us) == (999, 10)


def test_realtime_replies_wait_for_the_call_time(tmp_path):
    program = build("count_calls", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless(
        "--clock", "realtime", "--speed", "4", "--call-time", "4", "--program", f"1={program}", cwd=tmp_path
    )
    assert result.returncode == 0, result.stdout + result.stderr
    iterations, took = counted(result.stdout)
    # At most what 4 ms of simulation time per iteration allow; fewer as each round trip adds its own.
    assert 30 <= iterations <= 250
    assert took >= 100 * 4  # never less; more when the machine is slow
    stopped = float(re.search(r"stopped at t=([\d.]+) s", result.stdout).group(1))
    assert stopped >= 1.4
