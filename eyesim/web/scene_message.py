"""The `scene` message of the viewer channel, built from the simulation's scene description."""

from __future__ import annotations

from eyesim.physics.units import mm


def scene_message(sim, texture_url: str | None) -> dict:
    scene = sim.scene
    walls = [{"x1": mm(w.x1), "y1": mm(w.y1), "x2": mm(w.x2), "y2": mm(w.y2), "thickness": mm(w.thickness),
              "height": mm(w.height), "color": list(w.color)} for w in scene.world.walls]
    robots = []
    for robot in sim.robots:
        t = robot.type
        robots.append({"id": robot.id, "name": robot.name, "type": t.name,
                       "size": [mm(t.length), mm(t.width), mm(t.height)], "color": list(t.color),
                       "wheel_diameter": mm(t.wheels.diameter) if t.wheels else 0.0,
                       "track": mm(t.wheels.track) if t.wheels else 0.0})
    markers = [{"x": mm(m.x), "y": mm(m.y), "color": list(m.color)} for m in scene.markers]
    return {"type": "scene", "floor": {"width": sim.floor.width, "height": sim.floor.height, "texture": texture_url},
            "walls": walls, "robots": robots, "objects": [], "markers": markers,
            "settings": {"vis": scene.settings.vis, "trace": scene.settings.trace}}
