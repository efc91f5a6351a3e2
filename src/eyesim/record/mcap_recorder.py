"""Recording a run into an MCAP file (docs/recording.md), as an observer of the simulation.

The recorder watches from outside: a step observer samples poses, robot state and LCDs on
simulation time; a request observer sees the sensor readings, camera images and commands the
programs asked for; an event listener gets console lines, program exits, menus, inputs and scene
edits. The simulation thread only copies values; a writer thread encodes (JSON, PNG, JPEG) and
writes, in the order things happened, so a deterministic run gives the same recording."""

from __future__ import annotations

import base64
import dataclasses
import io
import json
import logging
import math
import queue
import threading
from pathlib import Path

import numpy as np
from mcap.writer import CompressionType, Writer
from PIL import Image

from eyesim import __version__
from eyesim.record import sampling, schemas
from eyesim.robot.components.lcd import Lcd
from eyesim.viewer import mesh_message, messages

DEFAULT_POSE_RATE = 100.0  # Hz of simulation time: the CSV's 10 ms rows
DEFAULT_LCD_RATE = 30.0  # Hz: at most this many LCD images per robot and simulated second
BATCH = 64  # messages handed to the writer thread at once: one wake-up of it, not one per message
QUEUE_LENGTH = 8  # batches waiting for the writer; beyond them the simulation waits (nothing is lost)
JPEG_QUALITY = 85
FLOOR_TEXTURE = "floor-texture"  # attachment names; meshes are "mesh/<kind>/<id>"
COMMAND_GROUPS = ("vw", "motor", "servo")
VIEWER_EVENTS = ("menu", "console", "program", "serial", "io", "audio", "reset")


def _is_command(op) -> bool:
    """Setters of the drive, motor and servo groups: what the program told its robot to do."""
    return op.group in COMMAND_GROUPS and bool(op.request) and not op.blocking and op.reply == (("result", "i32"),)


def _json(value) -> bytes:
    return json.dumps(value, separators=(",", ":")).encode()


def _image_message(time_us: int, frame: str, pixels, image_format: str) -> bytes:
    buffer = io.BytesIO()
    if image_format == "png":
        _png_image(pixels).save(buffer, format="PNG", compress_level=1)
    else:
        Image.fromarray(pixels).save(buffer, format="JPEG", quality=JPEG_QUALITY)
    return _json(
        {
            "timestamp": schemas.stamp(time_us),
            "frame_id": frame,
            "format": image_format,
            "data": base64.b64encode(buffer.getvalue()).decode("ascii"),
        }
    )


def _png_image(pixels) -> Image.Image:
    """An LCD's pixels as the image to write: one grey channel when they are grey (white text on
    black, the menu bar), the same picture in a third of the bytes to compress."""
    grey = pixels[..., 0]
    if np.array_equal(grey, pixels[..., 1]) and np.array_equal(grey, pixels[..., 2]):
        return Image.fromarray(np.ascontiguousarray(grey))
    return Image.fromarray(pixels)


def period_us(rate: float, step_us: int, what: str) -> int:
    """A sampling period in whole physics steps, for a rate in Hz; ValueError for a bad rate."""
    if not (isinstance(rate, (int, float)) and math.isfinite(rate) and rate > 0):
        raise ValueError(f"{what} {rate!r}: expected a rate in Hz above 0")
    steps = round(1e6 / rate / step_us)
    if steps < 1:
        raise ValueError(f"{what} {rate:g} Hz: at most {1e6 / step_us:g} Hz (one sample per physics step)")
    return steps * step_us


log = logging.getLogger("eyesim")


class Recorder:
    """Records `sim` into the MCAP file `path` from now until `close()` (or the end of a `with`).

    `pose_rate`: samples per simulated second of every pose and robot state (default 100: the
    CSV's rows); `lcd_rate`: at most this many LCD images per robot and simulated second.

    A file holds one run of one scene file. The viewer's scene editor changes the scene (robots
    added, moved, deleted ...): each edited scene is written into the same file, as another
    message on /scene at that time, with channels for robots it adds (eyesim.record.Recording
    reads the file as segments, one per scene). When another scene is *opened* (Scenes…, a new
    scene), this file is finished and the recording goes on in the next one, `<name>-2.mcap`,
    `<name>-3.mcap` ... (`paths` lists them)."""

    wants_lcd = False  # LCDs are sampled on simulation time, not at the viewer's publish ticks

    def __init__(self, sim, path: str | Path, pose_rate: float = DEFAULT_POSE_RATE, lcd_rate: float = DEFAULT_LCD_RATE):
        self.sim = sim
        self.path = Path(path)
        self.paths = [self.path]
        self.pose_period_us = period_us(pose_rate, sim.step_us, "pose rate")
        self.lcd_period_us = period_us(lcd_rate, sim.step_us, "LCD rate")
        self._closed = False
        self._open()
        sim.step_observers.append(self)
        sim.request_observers.append(self.on_request)
        sim.events.subscribe(self)

    def _open(self) -> None:
        """Start writing `self.path`: the scene as it is now, then what happens."""
        self._file = open(self.path, "wb")
        self._writer = Writer(self._file, compression=CompressionType.ZSTD)
        self._channels: dict[str, int] = {}
        self._schema_ids: dict[str, int] = {}
        self._segment = 0  # scenes written into this file before the current one (edits)
        self._sequence: dict[int, int] = {}
        self._lcd_versions: dict[int, int] = {}
        self._next_lcd_us = self.sim.time_us
        self._queue: queue.Queue = queue.Queue(QUEUE_LENGTH)
        self._batch: list[tuple] = []
        self._failure: BaseException | None = None
        self._start_file()
        self._thread = threading.Thread(target=self._write_loop, name="eyesim-recorder", daemon=True)
        self._thread.start()
        self._sample_lcds(self.sim)

    def _next_scene(self) -> None:
        """Another scene replaced the running one: finish this file, go on in the next."""
        try:
            self._finish_file(last_lcds=False)  # the robots whose LCDs it has are gone
        except OSError as error:  # this file is lost (a full disk); the next one may still work
            log.error("%s", error)
        stem = self.paths[0].stem
        self.path = self.paths[0].with_name(f"{stem}-{len(self.paths) + 1}{self.paths[0].suffix}")
        self.paths.append(self.path)
        log.info("the scene was replaced: the recording goes on in %s", self.path)
        self._open()

    def __enter__(self) -> "Recorder":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # -- the file's start: schemas, channels, metadata, attachments, the scene ----------------------
    def _start_file(self) -> None:
        sim = self.sim
        self._writer.start(profile=schemas.PROFILE, library=f"{schemas.LIBRARY} {__version__}")
        self._schema_ids = {
            name: self._writer.register_schema(name, "jsonschema", schemas.schema_bytes(name))
            for name in schemas.SCHEMAS
        }
        self._register([schemas.SCENE, schemas.TRANSFORMS, schemas.EVENTS, schemas.LOG, schemas.EDITS])
        self._writer.add_metadata(
            "eyesim",
            {
                "version": __version__,
                "start_time_s": repr(sim.time),
                "step_s": repr(sim.step_us / 1e6),
                "pose_rate_hz": repr(1e6 / self.pose_period_us),
                "lcd_rate_hz": repr(1e6 / self.lcd_period_us),
                "clock": sim.clock.mode,
            },
        )
        self._write_scene(*self._scene_parts())

    def _scene_parts(self) -> tuple:
        """What the file needs of the scene as it is now (on the simulation thread): its channels,
        attachments (floor texture, models; named for the segment after the first) and /scene message."""
        sim, segment = self.sim, self._segment
        suffix = "" if segment == 0 else f"@{segment}"
        query = "" if segment == 0 else f"?v={segment}"  # replay_server serves the segment's attachments
        # the rays' channel also without VIS: the settings panel may turn it on during the run
        topics = [schemas.RAYS] + [schemas.robot_topic(r.id, c) for r in sim.robots for c in schemas.ROBOT_CHANNELS]
        attachments = []
        texture = sim.scene.world.floor_texture
        has_texture = bool(texture) and Path(texture).is_file()
        if has_texture:
            attachments.append(
                (FLOOR_TEXTURE + suffix, "image/" + Path(texture).suffix[1:].lower(), Path(texture).read_bytes())
            )
        for kind, things in (("robot", sim.robots), ("object", sim.objects)):
            for thing in things:
                if mesh_message.has_mesh(sim, thing.body):
                    attachments.append(
                        (
                            f"mesh/{kind}/{thing.id}{suffix}",
                            "application/json",
                            _json(mesh_message.mesh_message(sim.world.model, thing.body)),
                        )
                    )
        viewer_scene = messages.scene(
            sim,
            "/scene/floor-texture" + query if has_texture else None,
            version=str(segment) if segment else None,
            new_scene=segment > 0,
        )
        description = json.loads(json.dumps(dataclasses.asdict(sim.scene), default=str))
        return sim.time_us, topics, attachments, _json({"viewer": viewer_scene, "description": description})

    def _register(self, topics: list[str]) -> None:
        for topic in topics:
            if topic not in self._channels:
                self._channels[topic] = self._writer.register_channel(
                    topic, "json", self._schema_ids[schemas.schema_of(topic)]
                )

    def _write_scene(self, time_us: int, topics: list[str], attachments: list[tuple], scene: bytes) -> None:
        """Channels, attachments and the /scene message of a scene (on the thread that writes)."""
        self._register(topics)
        for name, media_type, data in attachments:
            self._writer.add_attachment(0, time_us * 1000, name, media_type, data)
        self._add(schemas.SCENE, time_us, scene)

    def _scene_edited(self) -> None:
        """The scene editor changed the scene: the edited one goes into this file (a new segment)."""
        self._segment += 1
        parts = self._scene_parts()
        self._put(None, parts[0], lambda: self._write_scene(*parts))
        self._lcd_versions.clear()  # the robots are new: each one's LCD as it is now
        self._sample_lcds(self.sim)

    # -- observers, on the simulation thread --------------------------------------------------------
    def __call__(self, sim) -> None:
        """After every physics step."""
        now = sim.time_us
        if now % self.pose_period_us == 0:
            transforms = sampling.transforms(sim)
            self._put(schemas.TRANSFORMS, now, lambda: _json(transforms))
            for robot in sim.robots:
                state = sampling.robot_state(robot)
                self._put(schemas.robot_topic(robot.id, "state"), now, lambda state=state: _json(state))
            if sim.scene.settings.vis:
                rays = messages.sensor_rays(sim.robots)
                self._put(schemas.RAYS, now, lambda: _json({"rays": rays}))
        if now >= self._next_lcd_us:
            self._sample_lcds(sim)

    def _sample_lcds(self, sim) -> None:
        now = sim.time_us
        self._next_lcd_us = now + self.lcd_period_us
        for robot in sim.robots:
            lcd = robot.component(Lcd)
            if lcd is None or self._lcd_versions.get(robot.id) == lcd.version:
                continue
            self._lcd_versions[robot.id] = lcd.version
            pixels = lcd.screen().copy()
            frame = schemas.robot_frame(robot.id)
            self._put(
                schemas.robot_topic(robot.id, "lcd"), now, lambda p=pixels, f=frame: _image_message(now, f, p, "png")
            )

    def on_request(self, robot, request, reply) -> None:
        """A request the simulator answered at once: keep the readings and commands worth seeing
        (the readings are what the robot's components keep of their ops: robot/component.py)."""
        op, now = request.op, request.time_us
        if _is_command(op):
            args = {name: value for (name, _), value in zip(op.request, request.args)}
            self._put(
                schemas.robot_topic(robot.id, "command"), now, _json({"robot": robot.id, "op": op.name, "args": args})
            )
            return
        for component in robot.components:
            if op.code in component.recorded_ops:
                kept = component.recorded(op.code, request.args, reply)
                if kept is not None:
                    self._put(schemas.robot_topic(robot.id, kept[0]), now, _reading(robot.id, now, *kept))

    def on_event(self, message: dict) -> None:
        kind, now = message["type"], self.sim.time_us
        if kind == "new-scene":
            if message.get("opened", True):
                self._next_scene()
            else:
                self._scene_edited()
            return
        if kind == "input":
            values = {k: v for k, v in message.items() if k != "type"}
            self._put(schemas.robot_topic(message["robot"], "input"), now, _json(values))
        elif kind == "edit":
            self._put(schemas.EDITS, now, _json({k: v for k, v in message.items() if k != "type"}))
        elif kind in VIEWER_EVENTS:
            self._put(schemas.EVENTS, now, _json(message))
            line = _log_line(message)
            if line is not None:
                level, text = line
                self._put(
                    schemas.LOG,
                    now,
                    _json(
                        {
                            "timestamp": schemas.stamp(now),
                            "level": level,
                            "message": text,
                            "name": f"robot {message['robot']}",
                            "file": "",
                            "line": 0,
                        }
                    ),
                )

    def on_snapshot(self, message: dict) -> None:
        pass  # poses are sampled on simulation time (see __call__), not at wall-clock publish ticks

    # -- the end ------------------------------------------------------------------------------------
    def close(self) -> None:
        """Stops observing, writes what the LCDs show now, and finishes the file (its index)."""
        if self._closed:
            return
        self._closed = True
        sim = self.sim
        if self in sim.step_observers:
            sim.step_observers.remove(self)
        if self.on_request in sim.request_observers:
            sim.request_observers.remove(self.on_request)
        if self in sim.events.listeners:
            sim.events.unsubscribe(self)
        self._finish_file()

    def _finish_file(self, last_lcds: bool = True) -> None:
        """What the LCDs show now, then the file's end (its index)."""
        if last_lcds:
            self._sample_lcds(self.sim)
        self._hand_over()
        self._queue.put(None)
        self._thread.join()
        try:
            if self._failure is None:
                self._writer.finish()
        finally:
            self._file.close()
        if self._failure is not None:
            raise OSError(f"writing {self.path} failed: {self._failure}") from self._failure

    # -- writing ------------------------------------------------------------------------------------
    def _put(self, topic: str | None, time_us: int, payload) -> None:
        """Queue a message: `payload` is bytes, or a function that makes them on the writer thread
        (topic None: a function that writes something itself there, such as a scene)."""
        if self._failure is None:
            self._batch.append((topic, time_us, payload))
            if len(self._batch) >= BATCH:
                self._hand_over()

    def _hand_over(self) -> None:
        """The messages queued so far, to the writer thread."""
        if self._batch:
            self._queue.put(self._batch)
            self._batch = []

    def _write_loop(self) -> None:
        while (batch := self._queue.get()) is not None:
            for topic, time_us, payload in batch:
                if self._failure is not None:
                    break  # drain, so the simulation never blocks on a full queue
                try:
                    if topic is None:
                        payload()
                        continue
                    self._add(topic, time_us, payload if isinstance(payload, bytes) else payload())
                except Exception as error:  # a full disk: reported by close(), the run goes on
                    self._failure = error

    def _add(self, topic: str, time_us: int, data: bytes) -> None:
        channel = self._channels[topic]
        sequence = self._sequence.get(channel, 0)
        self._sequence[channel] = sequence + 1
        self._writer.add_message(
            channel, log_time=time_us * 1000, data=data, publish_time=time_us * 1000, sequence=sequence
        )


def _reading(robot_id: int, time_us: int, channel: str, value):
    """A component's reading as its channel's message: an image's pixels as a JPEG (encoded on the
    writer thread), a foxglove message stamped and placed on the robot's frame, another with the robot."""
    frame = schemas.robot_frame(robot_id)
    if isinstance(value, np.ndarray):
        return lambda: _image_message(time_us, frame, value, "jpeg")
    if schemas.schema_of(schemas.robot_topic(robot_id, channel)).startswith("foxglove."):
        return _json({"timestamp": schemas.stamp(time_us), "frame_id": frame, **value})
    return _json({"robot": robot_id, **value})


def _log_line(message: dict) -> tuple[int, str] | None:
    """Console output and program starts and exits as foxglove.Log lines."""
    if message["type"] == "console":
        level = schemas.LOG_ERROR if message["stream"] == "stderr" else schemas.LOG_INFO
        return level, message["text"].rstrip("\n")
    if message["type"] == "program":
        if message["event"] == "started":
            return schemas.LOG_INFO, f"program {message['name']} started"
        code = message["exit_code"]
        return (
            schemas.LOG_INFO if code == 0 else schemas.LOG_ERROR
        ), f"program {message['name']} exited with code {code}"
    return None
