"""The viewer's timeline (docs/viewer-channel.md, "Timeline"): the state at any time of a recording
or of the live run's recent history, sent as a `frame` of ordinary viewer messages.

A source (RecordingTimeline here, LiveHistory for a live run) answers what things were like at a
time; a FrameCursor per browser remembers what that browser was sent, so playing forward sends
only what changed and a jump back starts the robot panels afresh. A recording of a run whose scene
was edited has segments, one per scene (eyesim.record.recording): a frame in another segment than
the last one sent brings that segment's `scene` first, and its robot panels start afresh."""

from __future__ import annotations

import base64
import bisect
import inspect
import io
import json
import math
import reprlib
from collections import defaultdict

from PIL import Image

from eyesim.record import signals
from eyesim.viewer import plain_messages as viewer_messages

LATEST_KINDS = ("menu", "program", "io")  # only the last one before a time matters
STREAM_KINDS = ("console", "serial")  # everything before a time matters
STREAM_BACKLOG = 500  # chunks per robot sent when a panel starts afresh (the console keeps 50,000 characters)
PATH_STEP = 0.005  # m: a path gets a point once the robot moved this far (as the viewer's TRACE)


class EventIndex:
    """The viewer events of a timeline by kind and robot, in time order."""

    def __init__(self, max_stream: int | None = None):
        self._latest: dict[tuple[str, int], list[tuple[int, dict]]] = defaultdict(list)
        self._streams: dict[tuple[str, int], list[tuple[int, dict]]] = defaultdict(list)
        self._max_stream = max_stream  # console or serial chunks kept per robot (None: all)

    def add(self, time_us: int, message: dict) -> None:
        kind = message.get("type")
        if kind in LATEST_KINDS:
            self._latest[(kind, message["robot"])].append((time_us, message))
        elif kind in STREAM_KINDS:
            stream = self._streams[(kind, message["robot"])]
            stream.append((time_us, message))
            if self._max_stream is not None and len(stream) > self._max_stream:
                del stream[: len(stream) - self._max_stream]

    def latest(self, kind: str, robot_id: int, time_us: int) -> dict | None:
        events = self._latest.get((kind, robot_id), [])
        index = bisect.bisect_right(events, time_us, key=lambda e: e[0]) - 1
        return events[index][1] if index >= 0 else None

    def stream(self, kind: str, robot_id: int, after_us: float, until_us: int) -> list[dict]:
        """The events after `after_us` up to and including `until_us`."""
        events = self._streams.get((kind, robot_id), [])
        first = bisect.bisect_right(events, after_us, key=lambda e: e[0])
        return [e for _, e in events[first : bisect.bisect_right(events, until_us, key=lambda e: e[0])]]

    def forget_before(self, time_us: int) -> None:
        """Drops what no time from `time_us` on needs (bounded live history)."""
        for events in self._latest.values():
            keep = max(0, bisect.bisect_right(events, time_us, key=lambda e: e[0]) - 1)
            del events[:keep]
        for events in self._streams.values():
            del events[: bisect.bisect_left(events, time_us, key=lambda e: e[0])]


class RecordingTimeline:
    """A recording (eyesim.record.Recording) as a timeline source. `key` goes into the URLs of the
    floor texture and models of its scenes (`r=`), so that a page never shows another recording's
    from its cache."""

    def __init__(self, recording, key: str | None = None):
        self.recording = recording
        self.key = key
        self.robot_ids = recording.robot_ids
        self.start_us, self.end_us = recording.start_us, recording.end_us
        self.states, self.psd = recording.states, recording.psd
        self.events = EventIndex()
        for time_us, message in recording.events:
            self.events.add(time_us, message)
        self._segment_events = []
        bounds = [segment.first_event for segment in recording.segments] + [len(recording.events)]
        for first, end in zip(bounds, bounds[1:]):
            index = EventIndex()
            for time_us, message in recording.events[first:end]:
                index.add(time_us, message)
            self._segment_events.append(index)
        self._images: dict[tuple, str] = {}

    def segment_at(self, time_us: int):
        return self.recording.segment_at(time_us)

    def segment_events(self, segment) -> EventIndex:
        """The viewer events of one segment (a scene of the recording)."""
        return self._segment_events[segment.index]

    def scene_message(self, segment, new_scene: bool = False) -> dict:
        """The segment's `scene` message, with this timeline's key in its URLs."""
        scene = json.loads(json.dumps(segment.scene))
        if new_scene:
            scene["new_scene"] = True
        if self.key is not None:
            if scene["floor"].get("texture"):
                scene["floor"]["texture"] = _with_key(scene["floor"]["texture"], self.key)
            for thing in scene["robots"] + scene.get("objects", []):
                if "mesh" in thing:
                    thing["mesh"] = _with_key(thing["mesh"], self.key)
        return scene

    def snapshot_at(self, time_us: int) -> dict | None:
        return self.recording.snapshot_at(time_us)

    def robot_track(self, robot_id: int):
        return self.recording.robot_track(robot_id)

    def image_time(self, robot_id: int, kind: str, time_us: int) -> int | None:
        return self.recording.image_time(robot_id, kind, time_us)

    def image_message(self, robot_id: int, kind: str, image_us: int) -> str:
        key = (robot_id, kind, image_us)
        if key not in self._images:
            if len(self._images) > 256:
                self._images.clear()
            image = self.recording.image(robot_id, kind, image_us)
            if kind == "lcd":
                message = viewer_messages.lcd_encoded(robot_id, image["data"])
            else:
                width, height = Image.open(io.BytesIO(base64.b64decode(image["data"]))).size
                message = viewer_messages.camera_encoded(robot_id, width, height, image["data"])
            self._images[key] = json.dumps(message)
        return self._images[key]


class FrameCursor:
    """What one browser has been sent of a timeline."""

    def __init__(self):
        self.time_us: int | None = None
        self.sent: dict[tuple[str, int], object] = {}
        self.segment: int | None = None  # the recording's scene the browser shows (None: the first)

    async def frame(self, source, time_us: int) -> str:
        """The `frame` message for `time_us` (clamped to the source's range)."""
        time_us = min(max(time_us, source.start_us), source.end_us)
        segment = source.segment_at(time_us) if hasattr(source, "segment_at") else None
        messages: list[str] = []
        robot_ids, events = source.robot_ids, source.events
        if segment is not None:
            robot_ids, events = segment.robot_ids, source.segment_events(segment)
            if segment.index != (self.segment or 0):  # another scene: the world and the panels anew
                messages.append(json.dumps(source.scene_message(segment, new_scene=True)))
                self.time_us = None
            self.segment = segment.index
        # going on from the time shown last, or afresh (the first time, or back in time)
        after_us = self.time_us if self.time_us is not None and self.time_us <= time_us else -math.inf
        afresh = after_us == -math.inf
        if afresh:
            self.sent.clear()
        since_us = segment.start_us if segment is not None else -math.inf
        self.time_us = time_us
        for robot_id in robot_ids:
            await self._robot(source, events, robot_id, after_us, since_us, time_us, messages)
        snapshot = source.snapshot_at(time_us)
        if snapshot is not None:
            messages.append(json.dumps(snapshot))
        return viewer_messages.frame_text(
            time_us / 1e6, list(robot_ids) if afresh else [], messages, source.start_us / 1e6, source.end_us / 1e6
        )

    async def _robot(
        self, source, events, robot_id: int, after_us: float, since_us: float, time_us: int, messages: list[str]
    ) -> None:
        for kind in LATEST_KINDS:  # a panel that starts afresh (`clear`) has none of these
            event = events.latest(kind, robot_id, time_us)
            if event is not None and self.sent.get((kind, robot_id)) is not event:
                self.sent[(kind, robot_id)] = event
                messages.append(json.dumps(event))
        for kind in STREAM_KINDS:
            chunks = events.stream(kind, robot_id, after_us, time_us)
            messages.extend(json.dumps(chunk) for chunk in chunks[-STREAM_BACKLOG:])
        for kind in ("lcd", "camera"):
            shown = source.image_time(robot_id, kind, time_us)
            if shown is not None and shown < since_us:  # the image of a robot of an earlier scene
                shown = None
            if shown is not None and self.sent.get((kind, robot_id)) != shown:
                self.sent[(kind, robot_id)] = shown
                text = source.image_message(robot_id, kind, shown)
                messages.append(await text if inspect.isawaitable(text) else text)


def paths(source) -> dict:
    """The `paths` message: each robot's path, a point whenever it moved PATH_STEP, with its time."""
    robots = []
    for robot_id in source.robot_ids:
        times, poses = source.robot_track(robot_id)
        kept_times, points = [], []
        last = None
        for time_us, (x, y) in zip(times, poses[:, :2].tolist()):
            if last is None or math.hypot(x - last[0], y - last[1]) >= PATH_STEP:
                last = (x, y)
                kept_times.append(time_us / 1e6)
                points += [round(x, 4), round(y, 4)]
        robots.append({"id": robot_id, "times": kept_times, "points": points})
    return viewer_messages.paths(robots)


async def answer(source, cursor: FrameCursor, message: dict) -> str:
    """The reply to a timeline command (seek, signals, series, paths); ValueError for a bad one."""
    kind = message.get("type")
    if kind == "seek":
        seconds = message.get("time")
        if isinstance(seconds, bool) or not isinstance(seconds, (int, float)) or not _finite(seconds):
            raise ValueError(f"seek: time {reprlib.repr(seconds)} is not a number of seconds")
        seconds = min(max(seconds, -1e12), 1e12)  # the frame clamps it to the timeline; 1e308 s in us overflows
        return await cursor.frame(source, round(seconds * 1e6))
    if kind == "signals":
        return json.dumps(viewer_messages.signals(signals.catalogue(source)))
    if kind == "series":
        ids = message.get("ids")
        if not isinstance(ids, list) or not all(isinstance(i, str) for i in ids) or len(ids) > 32:
            raise ValueError("series: ids must be a list of up to 32 signal ids")
        found = []
        for signal_id in ids:
            values = signals.series(source, signal_id)
            if values is None:
                raise ValueError(f"series: no signal {reprlib.repr(signal_id)}")
            found.append({"id": signal_id, "times": values[0], "values": values[1]})
        return json.dumps(viewer_messages.series(found))
    if kind == "paths":
        return json.dumps(paths(source))
    raise ValueError(f"unknown message type {kind!r}")


def _with_key(url: str, key: str) -> str:
    return f"{url}{'&' if '?' in url else '?'}r={key}"


def _finite(number) -> bool:
    try:
        return math.isfinite(number)
    except OverflowError:  # an integer beyond floats: finite, far outside any timeline
        return True


TIMELINE_COMMANDS = ("seek", "signals", "series", "paths")
