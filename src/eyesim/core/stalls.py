"""Runs that cannot go on, and why. In a deterministic run time moves only while every program
waits in a RoBIOS call, so a program computing without calls holds the whole run still; and a
headless run whose programs all wait for a key that nothing will press goes on for ever. The
stall watch notices either for a few seconds of wall time and says once, per program, what it
waits for."""

from __future__ import annotations

import threading
import time
from typing import Callable

from eyesim.net.session import Deferred

STALL_SECONDS = 3.0  # of wall time without simulated time moving, before saying why
LOOK_EVERY = 0.25  # s of wall time between looks at the clock


def function_name(op_name: str) -> str:
    """The RoBIOS function of a protocol operation: KEY_WAIT -> KEYWait, VW_WAIT -> VWWait."""
    group, *words = op_name.split("_")
    return group + "".join(word if len(word) <= 2 else word.capitalize() for word in words)


def waits(sim, seconds: float) -> list[str]:
    """What each program of a stalled run waits for, one line each (on the simulation thread)."""
    lines = []
    for session in sim.sessions:
        if session.robot is None or session.closed:
            continue
        who = f"robot {session.robot.id} ({session.program or 'program'})"
        waiting = [request.op for request, pending in session.pending if not pending.background]
        if waiting and waiting[0].group == "key":
            lines.append(
                f"{who}: waiting in {function_name(waiting[0].name)} — press a key in the viewer or pass --key"
            )
        elif waiting:
            lines.append(f"{who}: waiting in {function_name(waiting[0].name)}")
        elif not session.queued:
            lines.append(f"{who}: no RoBIOS call for {seconds:.0f} s; deterministic time waits for it")
    for robot_id in sorted(sim.expected_programs):
        lines.append(
            f"robot {robot_id}: its program has not connected for {seconds:.0f} s; deterministic time waits for it"
        )
    return lines


def making_replies(sim) -> bool:
    """Whether the simulator itself is still making a reply a program waits for (a camera image on
    the render thread): time waits for the simulator then, not for a program, and a slow frame
    (a 5 MP image drawn in software on a loaded machine) is no stall."""
    return any(
        isinstance(pending, Deferred) and not pending.work.done()
        for session in sim.sessions
        for _, pending in session.pending
    )


def hung_status(lines: list[str]) -> str:
    """A grader's word for a stalled case: 'waiting for a key' or 'hung: computing without RoBIOS
    calls' (or what else it waits in)."""
    if any("press a key" in line for line in lines):
        return "waiting for a key"
    if any("no RoBIOS call" in line or "has not connected" in line for line in lines):
        return "hung: computing without RoBIOS calls"
    return "hung: " + "; ".join(line.split(": ", 1)[1] for line in lines) if lines else "hung"


class StallWatch:
    """A thread that watches the run and calls `report(lines)` once per stall: simulated time has not
    moved, or (`keys_can_come` False: no viewer) every program has been waiting for a key, for
    `seconds` of wall time."""

    def __init__(
        self, sim, report: Callable[[list[str]], None], seconds: float = STALL_SECONDS, keys_can_come: bool = True
    ):
        self.sim = sim
        self.report = report
        self.seconds = seconds
        self.keys_can_come = keys_can_come
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._watch, name="stall watch", daemon=True)

    def start(self) -> "StallWatch":
        self._thread.start()
        return self

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(timeout=2.0)

    def _watch(self) -> None:
        last, since, told = None, time.monotonic(), False
        while not self._stop.wait(LOOK_EVERY):
            now = time.monotonic()
            state = self._state()
            if state is None or state != last:
                last, since, told = state, now, False
            elif not told and now - since >= self.seconds:
                told = True
                lines = self._on_simulation(lambda sim, seconds=now - since: waits(sim, seconds))
                if lines:
                    self.report(lines)

    def _state(self):
        """What must stay the same for a stall: the simulated time, or, when no key can come, which
        calls for a key the programs wait in (None: neither holds still, or the run is paused)."""

        def look(sim):
            if sim.clock.paused or making_replies(sim):
                return None
            if self.keys_can_come:
                return sim.time_us
            live = [s for s in sim.sessions if s.robot is not None and not s.closed]
            keys = tuple(
                id(request)
                for s in live
                for request, pending in s.pending
                if request.op.group == "key" and not pending.background
            )
            all_wait_for_keys = live and len(keys) == len(live) and not sim.expected_programs
            return ("keys", keys) if all_wait_for_keys else sim.time_us

        return self._on_simulation(look)

    def _on_simulation(self, action):
        """`action(sim)`'s result, computed on the simulation thread (None if it does not answer)."""
        done = threading.Event()
        result = []

        def run(sim):
            result.append(action(sim))
            done.set()

        self.sim.call(run)
        return result[0] if done.wait(timeout=5.0) else None
