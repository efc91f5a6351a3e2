"""The viewer channel's messages made from plain values (docs/viewer-channel.md): poses and
snapshots, LCD and camera images, console and program lines, serial, audio, the timeline, plots'
signals and series, errors. Live runs and replays send them alike; those read from the running
simulation are in messages.py. This module needs no simulator (no MuJoCo), so reading a
recording (`eyesim export`, `plot`, `render`, `replay`) starts quickly."""

from __future__ import annotations

import base64
import io
import json

import numpy as np
from PIL import Image

CAMERA_VIEW_WIDTH = 320  # pixels: larger camera images are sent to the viewer scaled down by a whole factor


def snapshot_of(
    time: float, robots: list[dict], objects: list[dict], bodies: list[dict], rays: list[dict] | None = None
) -> dict:
    """A `snapshot` from its poses (also a recording's, eyesim/record/recording.py); rays only with VIS."""
    message = {"type": "snapshot", "time": time, "robots": robots, "objects": objects, "bodies": bodies}
    if rays is not None:
        message["rays"] = rays
    return message


def pose(thing_id: int, pos: list[float], quat: list[float], battery_volts: float | None = None) -> dict:
    entry = {"id": thing_id, "pos": pos, "quat": quat}
    if battery_volts is not None:
        entry["battery"] = round(battery_volts, 3)
    return entry


def lcd(robot_id: int, pixels: np.ndarray) -> dict:
    buffer = io.BytesIO()
    Image.fromarray(pixels).save(buffer, format="PNG", compress_level=1)
    return lcd_encoded(robot_id, base64.b64encode(buffer.getvalue()).decode("ascii"))


def lcd_encoded(robot_id: int, png_base64: str) -> dict:
    return {"type": "lcd", "robot": robot_id, "png": png_base64}


def camera(robot_id: int, pixels: np.ndarray) -> dict:
    height, width = pixels.shape[:2]
    step = max(1, width // CAMERA_VIEW_WIDTH)  # a panel shows no more: skip the rest early
    buffer = io.BytesIO()
    Image.fromarray(pixels[::step, ::step]).save(buffer, format="JPEG", quality=85)
    return camera_encoded(robot_id, width, height, base64.b64encode(buffer.getvalue()).decode("ascii"))


def camera_encoded(robot_id: int, width: int, height: int, jpeg_base64: str) -> dict:
    """`width` x `height`: the resolution the program took the image at."""
    return {"type": "camera", "robot": robot_id, "width": width, "height": height, "jpeg": jpeg_base64}


def console(robot_id: int, stream: str, text: str) -> dict:
    return {"type": "console", "robot": robot_id, "stream": stream, "text": text}


def program(robot_id: int, event: str, name: str, exit_code: int | None) -> dict:
    return {"type": "program", "robot": robot_id, "event": event, "name": name, "exit_code": exit_code}


def serial(robot_id: int, interface: int, data: bytes) -> dict:
    # Bytes as text one to one (Latin-1), so any byte survives JSON.
    return {"type": "serial", "robot": robot_id, "interface": interface, "text": data.decode("latin-1")}


def audio(robot_id: int, sound: dict) -> dict:
    return {"type": "audio", "robot": robot_id, **sound}


def timeline(mode: str, name: str | None = None, start: float | None = None, end: float | None = None) -> dict:
    message: dict[str, object] = {"type": "timeline", "mode": mode}
    if name is not None:
        message.update(name=name, start=start, end=end)
    return message


def frame_text(
    time: float, clear: list[int], message_texts: list[str], start: float | None = None, end: float | None = None
) -> str:
    """A `frame` as JSON text: its messages are already JSON (cached images), so they are joined, not re-encoded."""
    span = "" if start is None else f',"start":{start!r},"end":{end!r}'
    return (
        f'{{"type":"frame","time":{time!r}{span},"clear":{json.dumps(clear)},"messages":[{",".join(message_texts)}]}}'
    )


def signals(catalogue: list[dict]) -> dict:
    return {"type": "signals", "signals": catalogue}


def series(found: list[dict]) -> dict:
    return {"type": "series", "series": found}


def paths(robots: list[dict]) -> dict:
    return {"type": "paths", "robots": robots}


def error(text: str) -> dict:
    return {"type": "error", "message": text}
