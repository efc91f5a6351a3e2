"""Every message of the viewer channel, built from simulation state (docs/viewer-channel.md).

Each function returns one message as a dict (or JSON text where the message embeds others already
encoded); protocol/viewer.schema.json describes them and tests/web/test_viewer_messages.py checks
what a live simulator sends against it. A new message is one schema entry and one function here."""

from __future__ import annotations

import base64
import io
import json
from pathlib import Path

import numpy as np
from PIL import Image

from eyesim.physics.objects import shape_of
from eyesim.physics.units import mm
from eyesim.robot.components.analog_io import AnalogInputs
from eyesim.robot.components.battery import Battery
from eyesim.robot.components.digital_io import LINES, DigitalLines
from eyesim.robot.components.lcd import Lcd
from eyesim.scene.drives import drive_of
from eyesim.viewer.mesh_message import has_mesh, mesh_url

RAY_PRECISION = 3  # decimals of a metre: millimetres are plenty for a line on the screen
CAMERA_VIEW_WIDTH = 320  # pixels: larger camera images are sent to the viewer scaled down by a whole factor


# -- the world -------------------------------------------------------------------------------------
def scene(sim, texture_url: str | None, version: str | None = None, new_scene: bool = False) -> dict:
    """`version` goes into the models' URLs (`?v=`), so that another scene's are other URLs;
    `new_scene`: another scene replaced the running one (the robot panels start afresh)."""
    scene = sim.scene
    query = "" if version is None else f"?v={version}"
    walls = [
        {
            "x1": mm(w.x1),
            "y1": mm(w.y1),
            "x2": mm(w.x2),
            "y2": mm(w.y2),
            "thickness": mm(w.thickness),
            "height": mm(w.height),
            "color": list(w.color),
        }
        for w in scene.world.walls
    ]
    robots = []
    for robot in sim.robots:
        t = robot.type
        wheels = t.wheels if drive_of(t).viewer_wheels else None
        robots.append(
            {
                "id": robot.id,
                "name": robot.name,
                "type": t.name,
                "size": [mm(t.length), mm(t.width), mm(t.height)],
                "color": list(t.color),
                # Other drives' wheels come as robot bodies of their own (below).
                "wheel_diameter": mm(wheels.diameter) if wheels else 0.0,
                "track": mm(wheels.track) if wheels else 0.0,
            }
        )
        if has_mesh(sim, robot.body):  # its .obj model, drawn instead of the box (mesh_message.py)
            robots[-1]["mesh"] = mesh_url("robot", robot.id) + query
    markers = [{"x": mm(m.x), "y": mm(m.y), "color": list(m.color)} for m in scene.markers]
    model = sim.world.model
    objects = []
    for thing in sim.objects:
        parts = _shapes(model, thing.geoms)
        if parts:  # `shape` and `size` say what it mainly is; `parts` draw it
            objects.append(
                {
                    "id": thing.id,
                    "type": thing.type.name,
                    "color": list(thing.type.color),
                    "shape": parts[0]["shape"],
                    "size": parts[0]["size"],
                    "parts": parts,
                }
            )
            if thing.mesh_geoms:
                objects[-1]["mesh"] = mesh_url("object", thing.id) + query
    bodies = [
        {"id": body, "robot": robot.id, "parts": _shapes(model, _geoms(model, body), colored=True)}
        for robot in sim.robots
        for body in robot.shown_parts
    ]
    water = {"surface": sim.water.surface} if sim.water is not None else None
    return {
        "type": "scene",
        "name": Path(scene.source).name,
        "new_scene": new_scene,
        "floor": {"width": sim.floor.width, "height": sim.floor.height, "texture": texture_url},
        "walls": walls,
        "robots": robots,
        "objects": objects,
        "markers": markers,
        "bodies": bodies,
        "water": water,
        "warnings": [_warning(d) for d in scene.warnings],
        "settings": {"vis": scene.settings.vis, "trace": scene.settings.trace},
    }


def _warning(diagnostic) -> dict:
    """A loader warning as the viewer lists it (file:line and what was wrong)."""
    where = diagnostic.location
    return {
        "file": where.file,
        "line": where.line,
        "column": where.column,
        "code": diagnostic.code,
        "message": diagnostic.message,
    }


def _geoms(model, body: int) -> range:
    start = model.body_geomadr[body]
    return range(start, start + model.body_geomnum[body])


def _shapes(model, geoms, colored: bool = False) -> list[dict]:
    """The visible geoms as viewer shapes in their body's frame (invisible ones, alpha 0, skipped)."""
    shapes = []
    for geom in geoms:
        rgba = model.geom_rgba[geom]
        shape = shape_of(model, geom) if rgba[3] > 0 else None
        if shape is not None:
            if colored:
                shape["color"] = [round(float(c) * 255) for c in rgba[:3]]
            shapes.append(shape)
    return shapes


def snapshot(sim) -> dict:
    """Where everything is now in the simulation."""
    data = sim.world.data
    robots = []
    for r in sim.robots:
        battery = r.component(Battery)
        robots.append(
            pose(
                r.id,
                data.xpos[r.body].tolist(),
                data.xquat[r.body].tolist(),
                battery.volts if battery is not None else None,
            )
        )
    objects = [pose(o.id, data.xpos[o.body].tolist(), data.xquat[o.body].tolist()) for o in sim.objects]
    # Moving parts of robots (arm links, fingers, steered wheels), by their body number.
    bodies = [
        pose(body, data.xpos[body].tolist(), data.xquat[body].tolist())
        for robot in sim.robots
        for body in robot.shown_parts
    ]
    return snapshot_of(sim.time, robots, objects, bodies, sensor_rays(sim.robots) if sim.scene.settings.vis else None)


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


def sensor_rays(robots) -> list[dict]:
    """What the robots' components draw (their `overlay`, robot/component.py): per entry, lines
    from a common origin to each of its ends (m, world frame), such as a PSD's beam, a lidar's
    last scan or a pressed bumper."""
    return [
        {"robot": robot.id, **{key: _rounded(v) if isinstance(v, np.ndarray) else v for key, v in entry.items()}}
        for robot in robots
        for component in robot.components
        for entry in component.overlay()
    ]


def _rounded(values: np.ndarray) -> list[float]:
    return np.round(values, RAY_PRECISION).tolist()


def status(sim, real_time_factor: float | None, history_start: float | None = None) -> dict:
    speed = "max" if sim.clock.speed == float("inf") else sim.clock.speed
    message = {
        "type": "status",
        "time": sim.time,
        "paused": sim.clock.paused,
        "speed": speed,
        "clock": sim.clock.mode,
        "real_time_factor": real_time_factor,
    }
    if history_start is not None:
        message["history_start"] = history_start
    return message


# -- a robot's panel ------------------------------------------------------------------------------
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


def menu(robot) -> dict:
    screen = robot.component(Lcd)
    return {
        "type": "menu",
        "robot": robot.id,
        "labels": list(screen.menu or ["", "", "", ""]),
        "visible": screen.menu_visible,
        "rotated": screen.rotated,
    }


def console(robot_id: int, stream: str, text: str) -> dict:
    return {"type": "console", "robot": robot_id, "stream": stream, "text": text}


def program(robot_id: int, event: str, name: str, exit_code: int | None) -> dict:
    return {"type": "program", "robot": robot_id, "event": event, "name": name, "exit_code": exit_code}


def serial(robot_id: int, interface: int, data: bytes) -> dict:
    # Bytes as text one to one (Latin-1), so any byte survives JSON.
    return {"type": "serial", "robot": robot_id, "interface": interface, "text": data.decode("latin-1")}


def audio(robot_id: int, sound: dict) -> dict:
    return {"type": "audio", "robot": robot_id, **sound}


def robot_io(robot) -> dict | None:
    """A robot's digital lines and analog channels; None for a robot without them."""
    digital, analog = robot.component(DigitalLines), robot.component(AnalogInputs)
    if digital is None or analog is None:
        return None
    lines = [
        {"direction": digital.directions[k], "level": digital.read(k + 1), "driven": digital.driven[k]}
        for k in range(LINES)
    ]
    return {"type": "io", "robot": robot.id, "digital": lines, "analog": list(analog.values)}


# -- the timeline -----------------------------------------------------------------------------------
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
