"""The recent past of a live run, kept by the viewer hub so a browser can pause and scrub back
over it (docs/viewer.md, "Timeline"): snapshots with each robot's state, PSD readings, panel
events and the encoded LCD and camera images, for the last HISTORY_SECONDS of simulation time."""

from __future__ import annotations

import bisect
from collections import defaultdict

import numpy as np

from eyesim.web.timeline import EventIndex

HISTORY_SECONDS = 120
MAX_IMAGES = 1500  # per robot and kind: bounds memory when a program redraws its LCD all the time
MAX_CHUNKS = 2000  # console and serial chunks per robot: bounds memory when a program prints all the time
TRIM_EVERY = 64  # snapshots between trims


class LiveHistory:
    """A timeline source (eyesim/web/timeline.py) over the last HISTORY_SECONDS; used on the I/O loop."""

    def __init__(self, robot_ids: list[int], seconds: float = HISTORY_SECONDS):
        self.robot_ids = list(robot_ids)
        self.keep_us = round(seconds * 1e6)
        self.times: list[int] = []
        self.snapshots: list[dict] = []
        self.states: dict[int, list[tuple[int, dict]]] = defaultdict(list)
        self.psd: dict[int, list[tuple[int, dict]]] = defaultdict(list)
        self.events = EventIndex(MAX_CHUNKS)
        self.images: dict[tuple[int, str], list[tuple[int, object]]] = defaultdict(list)
        self._added = 0

    @property
    def start_us(self) -> int:
        return self.times[0] if self.times else 0

    @property
    def end_us(self) -> int:
        return self.times[-1] if self.times else 0

    # -- filling ------------------------------------------------------------------------------------
    def add_snapshot(self, snapshot: dict, states: list[dict]) -> None:
        time_us = round(snapshot["time"] * 1e6)
        if self.times and time_us < self.times[-1]:
            self.clear()  # time went back: a new simulation
        self.times.append(time_us)
        self.snapshots.append(snapshot)
        for state in states:
            self.states[state["robot"]].append((time_us, state))
        self._added += 1
        if self._added % TRIM_EVERY == 0:
            self._trim()

    def add_event(self, time_us: int, message: dict) -> None:
        self.events.add(time_us, message)

    def add_image(self, robot_id: int, kind: str, time_us: int, message) -> None:
        """`message`: the viewer message text, or a future of it (images are encoded in a worker)."""
        images = self.images[(robot_id, kind)]
        images.append((time_us, message))
        if len(images) > MAX_IMAGES:
            del images[:len(images) - MAX_IMAGES]

    def add_psd(self, robot_id: int, time_us: int, reading: dict) -> None:
        self.psd[robot_id].append((time_us, reading))

    def clear(self) -> None:
        self.__init__(self.robot_ids, self.keep_us / 1e6)

    def _trim(self) -> None:
        oldest = self.times[-1] - self.keep_us
        cut = bisect.bisect_left(self.times, oldest)
        del self.times[:cut], self.snapshots[:cut]
        for table in (self.states, self.psd):
            for samples in table.values():
                del samples[:bisect.bisect_left(samples, oldest, key=lambda s: s[0])]
        for images in self.images.values():
            # keep the last image before the oldest time: it is what the LCD showed then
            del images[:max(0, bisect.bisect_right(images, oldest, key=lambda s: s[0]) - 1)]
        self.events.forget_before(oldest)

    # -- the timeline source ------------------------------------------------------------------------
    def snapshot_at(self, time_us: int) -> dict | None:
        if not self.times:
            return None
        return self.snapshots[max(0, bisect.bisect_right(self.times, time_us) - 1)]

    def robot_track(self, robot_id: int):
        rows = [[*r["pos"], *r["quat"]] for s in self.snapshots for r in s["robots"] if r["id"] == robot_id]
        times = [t for t, s in zip(self.times, self.snapshots) if any(r["id"] == robot_id for r in s["robots"])]
        return times, np.array(rows, dtype=float).reshape(len(rows), 7)

    def image_time(self, robot_id: int, kind: str, time_us: int) -> int | None:
        """None before the first image kept: images are only made while a browser watches."""
        images = self.images.get((robot_id, kind), [])
        index = bisect.bisect_right(images, time_us, key=lambda s: s[0]) - 1
        return images[index][0] if index >= 0 else None

    def image_message(self, robot_id: int, kind: str, image_us: int):
        images = self.images[(robot_id, kind)]
        return images[bisect.bisect_left(images, image_us, key=lambda s: s[0])][1]
