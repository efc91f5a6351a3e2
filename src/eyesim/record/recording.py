"""Reading an EyeSim MCAP recording: checked on opening, indexed for seeking (docs/recording.md).

Opening reads the small messages once (poses, robot state, events) into arrays and lists; LCD and
camera images stay in the file and are fetched by time through the MCAP chunk index, so seeking
anywhere costs one chunk read. Anything wrong with the file raises RecordingError with a sentence
that says what.

A run whose scene was edited in the viewer holds one /scene message per scene (mcap_recorder.py):
the file is read as segments, each from its scene's time on (`segments`, `segment_at`). Edits
happen while paused, so several scenes may share a time: the last one is the one that ran."""

from __future__ import annotations

import bisect
import json
from collections import defaultdict
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from mcap.reader import SeekingReader

from eyesim.record import schemas
from eyesim.viewer import plain_messages

MAGIC = b"\x89MCAP0\r\n"
IMAGE_CHANNELS = ("lcd", "camera")


class RecordingError(Exception):
    """The file is missing, not a recording, damaged or truncated: the message says which."""


@dataclass
class Segment:
    """One scene of a recording: from `start_us` on (until the next segment), with the viewer's
    `scene` message and the scene description; `first_event` is the index in `Recording.events` of
    its first event (events at the same time as a scene change belong to the scene they came in)."""

    index: int
    start_us: int
    scene: dict
    description: dict
    first_event: int

    @property
    def robot_ids(self) -> list[int]:
        return [r["id"] for r in self.scene["robots"]]


class Recording:
    """An EyeSim recording opened for reading. Times are simulation microseconds."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self._file = _open(self.path)
        try:
            self._reader = SeekingReader(self._file, validate_crcs=True)
            self._load()
        except RecordingError:
            self._file.close()
            raise
        except Exception as error:  # MCAP's, zstandard's, JSON's errors have no common base class
            self._file.close()
            raise RecordingError(
                f"{self.path} is damaged and cannot be read ({error.__class__.__name__}: {error})"
            ) from None

    def close(self) -> None:
        self._file.close()

    def __enter__(self) -> "Recording":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # -- loading ------------------------------------------------------------------------------------
    def _load(self) -> None:
        summary = self._reader.get_summary()
        if summary is None or summary.statistics is None:
            raise RecordingError(
                f"{self.path} has no index: the recording was not finished "
                "(the simulator was killed?) or the file is truncated"
            )
        topics = {channel.topic for channel in summary.channels.values()}
        if schemas.SCENE not in topics:
            raise RecordingError(
                f"{self.path} is an MCAP file but not an EyeSim recording (it has no {schemas.SCENE} channel)"
            )
        self.metadata = {m.name: dict(m.metadata) for m in self._reader.iter_metadata()}
        self.segments: list[Segment] = []
        self.pose_times: list[int] = []
        self._frames: dict[str, int] = {}
        poses: list[list[float]] = []
        self.states: dict[int, list[tuple[int, dict]]] = defaultdict(list)
        self.rays: list[tuple[int, list]] = []
        self.events: list[tuple[int, dict]] = []
        self.inputs: list[tuple[int, dict]] = []
        self.edits: list[tuple[int, dict]] = []
        self.commands: list[tuple[int, dict]] = []
        self.psd: dict[int, list[tuple[int, dict]]] = defaultdict(list)
        self.lidar: dict[int, list[int]] = defaultdict(list)
        self.images: dict[tuple[int, str], list[int]] = defaultdict(list)  # (robot, lcd|camera) -> times
        for _, channel, message in self._reader.iter_messages():
            topic, time_us = channel.topic, message.log_time // 1000
            parts = topic.split("/")
            robot_channel = parts[3] if len(parts) == 4 and parts[1] == "robot" else None
            if robot_channel in IMAGE_CHANNELS:
                self.images[(int(parts[2]), robot_channel)].append(time_us)
                continue
            if robot_channel == "lidar":
                self.lidar[int(parts[2])].append(time_us)
                continue
            data = _decode(self.path, topic, time_us, message.data)
            if topic == schemas.SCENE:
                self.segments.append(
                    Segment(len(self.segments), time_us, data["viewer"], data["description"], len(self.events))
                )
            elif topic == schemas.TRANSFORMS:
                poses.append(self._pose_row(data))
                self.pose_times.append(time_us)
            elif topic == schemas.RAYS:
                self.rays.append((time_us, data["rays"]))
            elif topic == schemas.EVENTS:
                self.events.append((time_us, data))
            elif topic == schemas.EDITS:
                self.edits.append((time_us, data))
            elif robot_channel == "state":
                self.states[int(parts[2])].append((time_us, data))
            elif robot_channel == "psd":
                self.psd[int(parts[2])].append((time_us, data))
            elif robot_channel == "command":
                self.commands.append((time_us, data))
            elif robot_channel == "input":
                self.inputs.append((time_us, data))
        if not self.segments:
            raise RecordingError(
                f"{self.path} is an MCAP file but not an EyeSim recording (its {schemas.SCENE} channel is empty)"
            )
        first = self.segments[0]
        self.scene: dict = first.scene  # the first scene's (see segments)
        self.description: dict = first.description
        # Frames that came with an edited scene have no pose before it: NaN there.
        width = 7 * len(self._frames)
        poses = [row if len(row) == width else row + [np.nan] * (width - len(row)) for row in poses]
        self.poses = np.array(poses, dtype=np.float64).reshape(len(poses), len(self._frames), 7)
        self._event_times = [t for t, _ in self.events]
        self._ray_times = [t for t, _ in self.rays]
        self.start_us = round(float(self.metadata.get("eyesim", {}).get("start_time_s", "0")) * 1e6)
        self.end_us = max(self.start_us, summary.statistics.message_end_time // 1000)
        # every robot of every scene, in the order they came (plots and paths cover the whole run)
        self.robot_ids = list(dict.fromkeys(i for segment in self.segments for i in segment.robot_ids))
        self._segment_times = [segment.start_us for segment in self.segments]

    def _pose_row(self, data: dict) -> list[float]:
        """One sample's poses as a flat row (x, y, z, qw, qx, qy, qz per frame, frames in a fixed
        order; a frame it lacks is NaN, and frames an edited scene adds come at the end)."""
        for transform in data["transforms"]:
            self._frames.setdefault(transform["child_frame_id"], len(self._frames))
        row = [np.nan] * (7 * len(self._frames))
        for transform in data["transforms"]:
            index = self._frames[transform["child_frame_id"]]
            t, q = transform["translation"], transform["rotation"]
            row[7 * index : 7 * index + 7] = [t["x"], t["y"], t["z"], q["w"], q["x"], q["y"], q["z"]]
        return row

    def segment_at(self, time_us: int) -> Segment:
        """The scene that ran at `time_us` (the last of those that start then; the first before any)."""
        return self.segments[max(0, bisect.bisect_right(self._segment_times, time_us) - 1)]

    # -- poses --------------------------------------------------------------------------------------
    @property
    def duration_s(self) -> float:
        return (self.end_us - self.start_us) / 1e6

    def pose_index(self, time_us: int) -> int | None:
        """The last pose sample at or before `time_us` (the first one before it starts); None: no samples."""
        if not self.pose_times:
            return None
        return max(0, bisect.bisect_right(self.pose_times, time_us) - 1)

    def pose(self, frame: str, index: int) -> tuple[list[float], list[float]] | None:
        """(pos [x, y, z], quat [w, x, y, z]) of a frame (schemas.robot_frame(...) etc.) in sample `index`."""
        column = self._frames.get(frame)
        if column is None:
            return None
        values = self.poses[index, column]
        if np.isnan(values[0]):
            return None
        return values[:3].tolist(), values[3:].tolist()

    def robot_track(self, robot_id: int) -> tuple[list[int], np.ndarray]:
        """Sample times and (N, 7) poses of a robot over the whole recording: x, y, z, qw, qx, qy, qz."""
        column = self._frames.get(schemas.robot_frame(robot_id))
        if column is None:
            return [], np.zeros((0, 7))
        known = ~np.isnan(self.poses[:, column, 0])  # not before an edit added it, nor after one removed it
        return [t for t, k in zip(self.pose_times, known) if k], self.poses[known, column]

    def snapshot_at(self, time_us: int) -> dict | None:
        """The viewer's `snapshot` message as it was at `time_us`, or None before any pose sample."""
        index = self.pose_index(time_us)
        if index is None:
            return None
        sample_us = self.pose_times[index]
        scene = self.segment_at(time_us).scene
        robots = []
        for robot_id in (r["id"] for r in scene["robots"]):
            pose = self.pose(schemas.robot_frame(robot_id), index)
            if pose is not None:
                state = self._latest(self.states.get(robot_id, ()), sample_us)
                robots.append(plain_messages.pose(robot_id, pose[0], pose[1], state.get("battery") if state else None))
        objects = [
            plain_messages.pose(o["id"], p[0], p[1])
            for o in scene["objects"]
            if (p := self.pose(schemas.object_frame(o["id"]), index)) is not None
        ]
        bodies = [
            plain_messages.pose(b["id"], p[0], p[1])
            for b in scene["bodies"]
            if (p := self.pose(schemas.body_frame(b["id"]), index)) is not None
        ]
        rays = None
        if scene["settings"].get("vis"):
            at = bisect.bisect_right(self._ray_times, time_us) - 1
            rays = self.rays[at][1] if at >= 0 else []
        return plain_messages.snapshot_of(time_us / 1e6, robots, objects, bodies, rays)

    @staticmethod
    def _latest(samples, time_us: int):
        """The value of the last (time, value) at or before time_us in a time-sorted list."""
        index = bisect.bisect_right(samples, time_us, key=lambda s: s[0]) - 1
        return samples[index][1] if index >= 0 else None

    # -- events and images ---------------------------------------------------------------------------
    def events_until(self, time_us: int) -> list[dict]:
        """Viewer events (console, menu, program, ...) up to and including `time_us`, in order."""
        return [e for _, e in self.events[: bisect.bisect_right(self._event_times, time_us)]]

    def image_time(self, robot_id: int, kind: str, time_us: int) -> int | None:
        """The time of the robot's last LCD or camera image at or before `time_us`."""
        times = self.images.get((robot_id, kind), [])
        index = bisect.bisect_right(times, time_us) - 1
        return times[index] if index >= 0 else None

    def image(self, robot_id: int, kind: str, time_us: int) -> dict:
        """The foxglove.CompressedImage message the robot's `kind` (lcd/camera) channel has at exactly time_us."""
        topic = schemas.robot_topic(robot_id, kind)
        try:
            for _, _, message in self._reader.iter_messages(
                topics=[topic], starting_at=time_us * 1000, ending_at=time_us * 1000, reverse=True
            ):
                return _decode(self.path, topic, time_us, message.data)
        except Exception as error:  # as above
            raise RecordingError(f"{self.path} is damaged at t={time_us / 1e6:g} s: {error}") from None
        raise RecordingError(f"{self.path} has no {kind} image of robot {robot_id} at t={time_us / 1e6:g} s")

    def attachment(self, name: str) -> bytes | None:
        """An attachment's data (the floor texture, a robot's or object's mesh), or None."""
        for attachment in self._reader.iter_attachments():
            if attachment.name == name:
                return attachment.data
        return None


def _open(path: Path):
    try:
        file = open(path, "rb")
    except IsADirectoryError:
        raise RecordingError(f"{path} is a directory, not a recording") from None
    except OSError as error:
        raise RecordingError(f"cannot read {path}: {error.strerror}") from None
    head = file.read(len(MAGIC))
    if head != MAGIC:
        file.close()
        what = "empty" if not head else "not an MCAP file"
        raise RecordingError(f"{path} is {what}: expected a recording made with `eyesim run --record FILE.mcap`")
    file.seek(-len(MAGIC), 2)
    if file.read(len(MAGIC)) != MAGIC:
        file.close()
        raise RecordingError(
            f"{path} is truncated: the recording was not finished (the simulator was killed?) or the file was cut short"
        )
    file.seek(0)
    return file


def _decode(path: Path, topic: str, time_us: int, data: bytes):
    try:
        value = json.loads(data)
    except ValueError:
        raise RecordingError(
            f"{path} is damaged: the message on {topic} at t={time_us / 1e6:g} s is not JSON"
        ) from None
    if not isinstance(value, dict):
        raise RecordingError(f"{path} is damaged: the message on {topic} at t={time_us / 1e6:g} s is not a JSON object")
    return value
