"""Step while paused (docs/viewer.md, Timeline): the engine's `step_for` and the viewer's `step`
command let simulation time go on by one physics step (or a given time) and pause again, in every
clock mode; a deterministic run holds still while paused."""

import concurrent.futures
import sys
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.scenes import arena  # noqa: E402
from support.simulator import running_simulation  # noqa: E402

from eyesim.core.engine import DEFAULT_STEP_US  # noqa: E402

WAIT_S = 20


def on_sim(sim, action):
    """action(sim) on the simulation thread; its result."""
    future = concurrent.futures.Future()
    sim.call(lambda s: future.set_result(action(s)))
    return future.result(timeout=WAIT_S)


def until(condition, sim):
    """Wait until condition(sim), asked on the simulation thread, holds."""
    deadline = time.monotonic() + WAIT_S
    while not on_sim(sim, condition):
        assert time.monotonic() < deadline, "the condition never held"


def paused_at(sim) -> int:
    on_sim(sim, lambda s: s.clock.set_paused(True, s.time_us))
    return on_sim(sim, lambda s: s.time_us)


@pytest.mark.parametrize("mode, speed", [("realtime", 1.0), ("realtime", float("inf")), ("deterministic", 1.0)])
def test_a_step_is_one_physics_step_then_paused_again(mode, speed):
    with running_simulation(arena(), mode, speed) as (sim, _):
        start = paused_at(sim)
        assert on_sim(sim, lambda s: s.time_us) == start  # paused: time holds still, in every mode
        on_sim(sim, lambda s: s.step_for(0))
        until(lambda s: s.clock.paused and s.time_us > start, sim)
        assert on_sim(sim, lambda s: s.time_us) == start + DEFAULT_STEP_US
        on_sim(sim, lambda s: s.step_for(10_000))  # Shift: 10 ms, in whole steps
        until(lambda s: s.clock.paused and s.time_us > start + DEFAULT_STEP_US, sim)
        assert on_sim(sim, lambda s: s.time_us) == start + DEFAULT_STEP_US + 10_000
        on_sim(sim, lambda s: s.step_for(3_000))  # rounded up to whole steps
        until(lambda s: s.clock.paused and s.time_us > start + DEFAULT_STEP_US + 10_000, sim)
        assert on_sim(sim, lambda s: s.time_us) == start + DEFAULT_STEP_US + 10_000 + 2 * DEFAULT_STEP_US


def test_a_step_while_running_pauses_after_it():
    with running_simulation(arena(), "realtime", float("inf")) as (sim, _):
        on_sim(sim, lambda s: s.step_for(0))
        until(lambda s: s.clock.paused, sim)
        stopped = on_sim(sim, lambda s: s.time_us)
        assert stopped > 0 and stopped % DEFAULT_STEP_US == 0
        assert on_sim(sim, lambda s: s.time_us) == stopped
