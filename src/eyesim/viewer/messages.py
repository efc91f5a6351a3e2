"""The viewer channel's messages read from the running simulation (docs/viewer-channel.md): the
scene, snapshots, status, a robot's menu and I/O. Messages made from plain values (poses, images,
console lines, the timeline), which replays send too, are in plain_messages.py, so reading a
recording does not load the simulator.

Each function returns one message as a dict; interface/viewer.schema.json describes them and
tests/web/test_viewer_messages.py checks what a live simulator sends against it. A new message is
one schema entry and one function here or there."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from eyesim.physics.objects import shape_of
from eyesim.physics.units import mm
from eyesim.robot.components.analog_io import AnalogInputs
from eyesim.robot.components.battery import Battery
from eyesim.robot.components.digital_io import LINES, DigitalLines
from eyesim.robot.components.lcd import Lcd
from eyesim.scene.drives import drive_of
from eyesim.viewer.mesh_message import has_mesh, mesh_url
from eyesim.viewer.plain_messages import pose, snapshot_of

RAY_PRECISION = 3  # decimals of a metre: millimetres are plenty for a line on the screen


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
def menu(robot) -> dict:
    screen = robot.component(Lcd)
    return {
        "type": "menu",
        "robot": robot.id,
        "labels": list(screen.menu or ["", "", "", ""]),
        "visible": screen.menu_visible,
        "rotated": screen.rotated,
    }


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
