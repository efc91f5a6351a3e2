"""What a call costs in simulation time follows the real robot (docs/protocol.md#what-a-call-costs):
calls that reach the robot's hardware or the world take the call time, what the EyeBot does itself
(LCD drawing, reading the clock) only microseconds. Real C programs, run headless (deterministic)."""

import re

import pytest
from support.programs import build, run_headless

from eyesim.core.engine import DEFAULT_CALL_TIME_US
from eyesim.protocol import generated as g

PIXEL_US = g.OPS_BY_NAME["LCD_PIXEL"].cost_us


@pytest.fixture(scope="module")
def out(tmp_path_factory):
    return tmp_path_factory.mktemp("call_cost")


def test_a_screen_drawn_pixel_by_pixel_is_ready_before_the_key_meant_for_it(out):
    """3 600 LCDPixel calls per screen, then KEYGet: each scripted key lands on the screen it was
    meant for (at 4 ms a pixel the first screen took 14.4 s, and both keys came while drawing)."""
    program = build("redraw_then_key", out, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--key", "1:KEY1@0.5", "--key", "1:KEY2@1.0", "--program", f"1={program}", cwd=out)
    assert result.returncode == 0, result.stdout + result.stderr
    screens = [
        tuple(map(int, m)) for m in re.findall(r"screen (\d) ready at (\d+) ms, key (\d+) at (\d+) ms", result.stdout)
    ]
    assert len(screens) == 2, result.stdout
    (_, ready1, key1, at1), (_, ready2, key2, at2) = screens
    assert ready1 <= 3600 * PIXEL_US // 1000 + 1 < 500 <= at1 and key1 == 1  # KEY1
    assert at1 <= ready2 < 1000 <= at2 and key2 == 2  # KEY2
    took = int(re.search(r"map of 16000 areas took (\d+) ms", result.stdout).group(1))
    assert took <= 16000 * g.OPS_BY_NAME["LCD_AREA"].cost_us // 1000 + 1  # 160 ms, not 64 s


def test_polling_loops_take_the_time_they_took_and_a_local_loop_lets_time_pass(out):
    program = build("poll_loops", out, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--until", "2.7", "--program", f"1={program}", cwd=out)
    assert result.returncode == 0, result.stdout + result.stderr
    # PSDGet and VWGetPosition reach the robot: the call time each, as before the cost classes
    took = int(re.search(r"250 sensor turns took (\d+) ms", result.stdout).group(1))
    assert took == 250 * 2 * DEFAULT_CALL_TIME_US // 1000
    # polling the clock alone: it shows a later millisecond at every read, so the wait ends
    reads = int(re.search(r"waited 500 ms in (\d+) clock reads", result.stdout).group(1))
    assert 498 <= reads <= 500
    # an endless loop of LCD calls: its microseconds add up, so --until still ends the run
    assert "stopped at t=2.700 s" in result.stdout
    assert "poll_loops: still running at the end (stopped)" in result.stdout
    again = run_headless("--until", "2.7", "--program", f"1={program}", cwd=out)
    assert re.findall(r"\[robot 1\].*", again.stdout) == re.findall(r"\[robot 1\].*", result.stdout)
