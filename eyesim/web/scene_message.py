"""The `scene` message of the viewer channel, built from the simulation's scene description."""

from __future__ import annotations

from eyesim.physics.objects import shape_of
from eyesim.physics.units import mm
from eyesim.robot.drives import drive_of
from eyesim.web.mesh_message import has_mesh, mesh_url


def scene_message(sim, texture_url: str | None) -> dict:
    scene = sim.scene
    walls = [{"x1": mm(w.x1), "y1": mm(w.y1), "x2": mm(w.x2), "y2": mm(w.y2), "thickness": mm(w.thickness),
              "height": mm(w.height), "color": list(w.color)} for w in scene.world.walls]
    robots = []
    for robot in sim.robots:
        t = robot.type
        wheels = t.wheels if drive_of(t).viewer_wheels else None
        robots.append({"id": robot.id, "name": robot.name, "type": t.name,
                       "size": [mm(t.length), mm(t.width), mm(t.height)], "color": list(t.color),
                       # Other drives' wheels come as robot bodies of their own (below).
                       "wheel_diameter": mm(wheels.diameter) if wheels else 0.0,
                       "track": mm(wheels.track) if wheels else 0.0})
        if has_mesh(sim, robot.body):  # its .obj model, drawn instead of the box (mesh_message.py)
            robots[-1]["mesh"] = mesh_url("robot", robot.id)
    markers = [{"x": mm(m.x), "y": mm(m.y), "color": list(m.color)} for m in scene.markers]
    model = sim.world.model
    objects = []
    for thing in sim.objects:
        parts = _shapes(model, thing.geoms)
        if parts:  # `shape` and `size` say what it mainly is; `parts` draw it
            objects.append({"id": thing.id, "type": thing.type.name, "color": list(thing.type.color),
                            "shape": parts[0]["shape"], "size": parts[0]["size"], "parts": parts})
            if thing.mesh_geoms:
                objects[-1]["mesh"] = mesh_url("object", thing.id)
    bodies = [{"id": body, "robot": robot.id, "parts": _shapes(model, _geoms(model, body), colored=True)}
              for robot in sim.robots for body in robot.shown_parts]
    water = {"surface": sim.water.surface} if sim.water is not None else None
    return {"type": "scene", "floor": {"width": sim.floor.width, "height": sim.floor.height, "texture": texture_url},
            "walls": walls, "robots": robots, "objects": objects, "markers": markers, "bodies": bodies,
            "water": water,
            "warnings": [_warning(d) for d in scene.warnings],
            "settings": {"vis": scene.settings.vis, "trace": scene.settings.trace}}


def _warning(diagnostic) -> dict:
    """A loader warning as the viewer lists it (file:line and what was wrong)."""
    where = diagnostic.location
    return {"file": where.file, "line": where.line, "column": where.column, "code": diagnostic.code,
            "message": diagnostic.message}


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
