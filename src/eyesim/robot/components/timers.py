"""The program's timers (OSAttachTimer): periods in simulation time, due times kept by the simulator."""

from __future__ import annotations

from dataclasses import dataclass

from eyesim.robot.component import Component

MAX_TIMERS = 32


@dataclass
class Timer:
    handle: int
    period_us: int
    due_us: int


class ProgramTimers(Component):
    """Timers belong to the program that attached them: when another program (a new connection)
    uses them, the old program's timers are gone. They survive a world reset, like the program."""

    def __init__(self):
        self.owner = None
        self.timers: dict[int, Timer] = {}

    def _claim(self, owner) -> None:
        if owner is not self.owner:
            self.owner, self.timers = owner, {}

    def attach(self, owner, period_ms: int, now_us: int) -> int:
        """A new timer due every `period_ms` from `now_us` on; returns its handle (1..MAX_TIMERS)."""
        self._claim(owner)
        if period_ms <= 0:
            raise ValueError(f"timer period {period_ms} ms is not positive")
        free = [h for h in range(1, MAX_TIMERS + 1) if h not in self.timers]
        if not free:
            raise ValueError(f"all {MAX_TIMERS} timers are attached; detach one first")
        period_us = period_ms * 1000
        self.timers[free[0]] = Timer(free[0], period_us, now_us + period_us)
        return free[0]

    def detach(self, owner, handle: int) -> None:
        self._claim(owner)
        if self.timers.pop(handle, None) is None:
            raise ValueError(f"no timer {handle} is attached")

    def next_due_us(self, owner) -> int | None:
        if owner is not self.owner or not self.timers:
            return None
        return min(timer.due_us for timer in self.timers.values())

    def take_due(self, owner, at_us: int) -> list[int]:
        """Handles of the timers due at `at_us` (ascending); each moves on to its next period.
        Periods that passed entirely (a callback slower than its period) are skipped."""
        if owner is not self.owner:
            return []
        due = sorted(h for h, timer in self.timers.items() if timer.due_us <= at_us)
        for handle in due:
            timer = self.timers[handle]
            missed = (at_us - timer.due_us) // timer.period_us
            timer.due_us += (missed + 1) * timer.period_us
        return due


def create(context) -> list[Component]:
    return [ProgramTimers()]
