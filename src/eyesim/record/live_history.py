"""The recent past of a live run, kept by the viewer hub so a browser can pause and scrub back
over it (docs/viewer.md, "Timeline"): snapshots with each robot's state, PSD readings, panel
events and the encoded LCD and camera images, for the last HISTORY_SECONDS of simulation time.

Snapshots, states and PSD readings are kept compactly, as JSON text and arrays of numbers, and
parsed again only when a browser looks back: kept as dicts and lists, a busy run's two minutes
were millions of small objects that every pass of Python's garbage collector walked (pauses of
up to a second for everyone; docs/performance.md, "Reliability")."""

from __future__ import annotations

import bisect
import json
from array import array
from collections import defaultdict

import numpy as np

from eyesim.record.timeline import EventIndex

HISTORY_SECONDS = 120
MAX_IMAGES = 1500  # per robot and kind: bounds memory when a program redraws its LCD all the time
MAX_CHUNKS = 2000  # console and serial chunks per robot: bounds memory when a program prints all the time
TRIM_EVERY = 64  # snapshots between trims
POSE = 7  # numbers per pose in a robot's track: x, y, z and the quaternion w, x, y, z


class EncodedSamples:
    """(time_us, message) samples in time order, each message kept as JSON text and parsed when
    read: reads as a list of (time_us, dict) (eyesim/record/signals.py reads states and PSD so)."""

    def __init__(self):
        self.times = array("q")
        self.texts: list[str] = []

    def append(self, time_us: int, message: dict) -> None:
        self.times.append(time_us)
        self.texts.append(json.dumps(message, separators=(",", ":")))

    def drop_last(self) -> None:
        self.times.pop()
        self.texts.pop()

    def forget_before(self, time_us: int) -> None:
        cut = bisect.bisect_left(self.times, time_us)
        del self.times[:cut], self.texts[:cut]

    def __len__(self) -> int:
        return len(self.texts)

    def __getitem__(self, index: int) -> tuple[int, dict]:
        return self.times[index], json.loads(self.texts[index])

    def __iter__(self):
        for time_us, text in zip(self.times, self.texts):
            yield time_us, json.loads(text)


class LiveHistory:
    """A timeline source (eyesim/record/timeline.py) over the last HISTORY_SECONDS; used on the I/O loop."""

    def __init__(self, robot_ids: list[int], seconds: float = HISTORY_SECONDS):
        self.robot_ids = list(robot_ids)
        self.keep_us = round(seconds * 1e6)
        self.clear()

    def clear(self) -> None:
        """Forget all history (time went back: a new simulation)."""
        self.times = array("q")  # of the snapshots
        self.snapshots: list[str] = []  # as JSON text
        self.tracks: dict[int, tuple[array, array]] = defaultdict(lambda: (array("q"), array("d")))  # times, poses
        self.states: dict[int, EncodedSamples] = defaultdict(EncodedSamples)
        self.psd: dict[int, EncodedSamples] = defaultdict(EncodedSamples)
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
        if self.times and time_us == self.times[-1]:
            self._drop_last()  # paused: one sample per time, the latest (a robot dragged meanwhile)
        self.times.append(time_us)
        self.snapshots.append(json.dumps(snapshot, separators=(",", ":")))
        for robot in snapshot["robots"]:
            times, poses = self.tracks[robot["id"]]
            times.append(time_us)
            poses.extend(robot["pos"])
            poses.extend(robot["quat"])
        for state in states:
            self.states[state["robot"]].append(time_us, state)
        self._added += 1
        if self._added % TRIM_EVERY == 0:
            self._trim()

    def _drop_last(self) -> None:
        time_us = self.times.pop()
        self.snapshots.pop()
        for times, poses in self.tracks.values():
            if times and times[-1] == time_us:
                times.pop()
                del poses[-POSE:]
        for samples in self.states.values():
            if samples.times and samples.times[-1] == time_us:
                samples.drop_last()

    def add_event(self, time_us: int, message: dict) -> None:
        self.events.add(time_us, message)

    def add_image(self, robot_id: int, kind: str, time_us: int, message) -> None:
        """`message`: the viewer message text, or a future of it (images are encoded in a worker)."""
        images = self.images[(robot_id, kind)]
        images.append((time_us, message))
        if len(images) > MAX_IMAGES:
            del images[: len(images) - MAX_IMAGES]

    def add_psd(self, robot_id: int, time_us: int, reading: dict) -> None:
        self.psd[robot_id].append(time_us, reading)

    def _trim(self) -> None:
        oldest = self.times[-1] - self.keep_us
        cut = bisect.bisect_left(self.times, oldest)
        del self.times[:cut], self.snapshots[:cut]
        for times, poses in self.tracks.values():
            cut = bisect.bisect_left(times, oldest)
            del times[:cut], poses[: cut * POSE]
        for table in (self.states, self.psd):
            for samples in table.values():
                samples.forget_before(oldest)
        for images in self.images.values():
            # keep the last image before the oldest time: it is what the LCD showed then
            del images[: max(0, bisect.bisect_right(images, oldest, key=lambda s: s[0]) - 1)]
        self.events.forget_before(oldest)

    # -- the timeline source ------------------------------------------------------------------------
    def snapshot_at(self, time_us: int) -> dict | None:
        if not self.times:
            return None
        return json.loads(self.snapshots[max(0, bisect.bisect_right(self.times, time_us) - 1)])

    def robot_track(self, robot_id: int):
        times, poses = self.tracks.get(robot_id, (array("q"), array("d")))
        return list(times), np.frombuffer(poses, dtype=float).reshape(len(times), POSE).copy()

    def image_time(self, robot_id: int, kind: str, time_us: int) -> int | None:
        """None before the first image kept: images are only made while a browser watches."""
        images = self.images.get((robot_id, kind), [])
        index = bisect.bisect_right(images, time_us, key=lambda s: s[0]) - 1
        return images[index][0] if index >= 0 else None

    def image_message(self, robot_id: int, kind: str, image_us: int):
        images = self.images[(robot_id, kind)]
        return images[bisect.bisect_left(images, image_us, key=lambda s: s[0])][1]
