"""The stall watch says why a run stands still, but not while the simulator itself is still making a
reply a program waits for (a camera image drawn slowly on a loaded machine)."""

from __future__ import annotations

import threading
from types import SimpleNamespace

from eyesim.core.stalls import StallWatch
from eyesim.net.session import Deferred
from eyesim.protocol import generated


class Frame:
    """A render thread's piece of work that ends when the test says so."""

    def __init__(self):
        self.finished = threading.Event()
        self.error = None

    def done(self) -> bool:
        return self.finished.is_set()

    def cancel(self) -> None:
        pass


class StandingRun:
    """A run whose simulated time stands still, with one program waiting in CAMGet; it counts the
    stall watch's looks."""

    def __init__(self, frame: Frame):
        request = SimpleNamespace(op=generated.OPS_BY_NAME["CAM_GET"])
        self.session = SimpleNamespace(
            robot=SimpleNamespace(id=1), program="track", closed=False, queued=(), pending=[(request, Deferred(frame))]
        )
        self.sessions = [self.session]
        self.clock = SimpleNamespace(paused=False)
        self.time_us = 4_000
        self.expected_programs: set[int] = set()
        self.looks = 0
        self.looked = threading.Condition()

    def call(self, action) -> None:
        action(self)
        with self.looked:
            self.looks += 1
            self.looked.notify_all()

    def wait_for_looks(self, count: int) -> None:
        with self.looked:
            assert self.looked.wait_for(lambda: self.looks >= count, timeout=30), "the watch stopped looking"


def test_a_reply_the_simulator_is_still_making_is_no_stall_and_a_finished_one_can_be():
    frame = Frame()
    run = StandingRun(frame)
    reports: list[list[str]] = []
    said = threading.Event()
    watch = StallWatch(run, lambda lines: (reports.append(lines), said.set()), seconds=0.3).start()
    try:
        # Looks come LOOK_EVERY (0.25 s) apart: eight span over five times the stall time.
        run.wait_for_looks(8)
        assert reports == []
        frame.finished.set()  # the image is made, but time still does not move: now it is a stall
        assert said.wait(timeout=30)
        assert reports == [["robot 1 (track): waiting in CAMGet"]]
    finally:
        watch.stop()
