"""Simulation time: realtime (follows the wall clock times a speed factor) and deterministic.

Simulation time is kept in integer microseconds so that deterministic runs add up exactly.
In deterministic mode time is virtual: the engine advances it in lock-step with the connected
programs (see schedules.py); this module only carries the mode. In realtime mode the clock says how
many physics steps are due by now, given the speed factor and pauses."""

from __future__ import annotations

import math
import time

REALTIME = "realtime"
DETERMINISTIC = "deterministic"
MAX_SPEED = math.inf
# Simulation time an ordinary call takes (docs/running.md#call-time): EyeSim answered in a few ms,
# and lab programs that count loop iterations instead of time were written against that.
DEFAULT_CALL_TIME_US = 4000


class Clock:
    def __init__(self, mode: str = REALTIME, speed: float = 1.0, paused: bool = False):
        if mode not in (REALTIME, DETERMINISTIC):
            raise ValueError(f"unknown clock mode {mode!r}")
        if not speed > 0:
            raise ValueError("speed must be positive")
        self.mode = mode  # for the life of the clock
        self.deterministic = mode == DETERMINISTIC  # asked several times a call: an attribute
        self.speed = speed
        # Asked by every round of the simulation loop: an attribute, kept with the speed.
        self.as_fast_as_possible = mode == DETERMINISTIC or speed == MAX_SPEED
        self.paused = paused
        self._anchor_wall = time.perf_counter()
        self._anchor_sim_us = 0

    def anchor(self, sim_time_us: int) -> None:
        """Restart wall-clock pacing from the current simulation time (after pause/speed change)."""
        self._anchor_wall = time.perf_counter()
        self._anchor_sim_us = sim_time_us

    def set_speed(self, speed: float, sim_time_us: int) -> None:
        if not speed > 0:
            raise ValueError("speed must be positive")
        self.speed = speed
        self.as_fast_as_possible = self.deterministic or speed == MAX_SPEED
        self.anchor(sim_time_us)

    def set_paused(self, paused: bool, sim_time_us: int) -> None:
        self.paused = paused
        self.anchor(sim_time_us)

    def target_us(self) -> float:
        """The simulation time the wall clock says we should be at now (realtime mode)."""
        return self._anchor_sim_us + (time.perf_counter() - self._anchor_wall) * 1e6 * self.speed

    def seconds_until(self, sim_time_us: int) -> float:
        """Wall seconds until the simulation should reach `sim_time_us` (<= 0: it is due)."""
        return (sim_time_us - self.target_us()) / 1e6 / self.speed
