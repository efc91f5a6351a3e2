"""Scene description -> MuJoCo world: floor, walls, markers, water, objects and robots, in one model."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.physics.meshes import model_mesh
from eyesim.physics.objects import SceneObject, add_object
from eyesim.physics.water import Water, WaterForces, object_water_forces, water_of
from eyesim.physics.world import Floor, PhysicsWorld, add_floor, add_marker, add_wall, floor_of, new_spec
from eyesim.robot.build import add_robot
from eyesim.robot.robot import Robot
from eyesim.scene.description import Diagnostic, Location, Scene
from eyesim.scene.diagnostics import SceneError

# Triangles of all the scene's models together: each placement of a model is drawn (and held by
# MuJoCo) again, so 50 placements of a million-triangle model took 24 GB. Far above real scenes.
MAX_SCENE_TRIANGLES = 2_000_000


@dataclass
class BuiltWorld:
    world: PhysicsWorld
    floor: Floor
    water: Water | None
    robots: list[Robot]
    objects: list[SceneObject]
    floating: list[WaterForces] = field(default_factory=list)  # objects the water lifts


def build_world(scene: Scene, timestep: float) -> BuiltWorld:
    """Robots are numbered 1..n and objects 1..m in scene order (the SIM functions' ids). SceneError
    when the scene's models hold more than MAX_SCENE_TRIANGLES triangles together."""
    _check_triangles(scene)
    spec = new_spec(timestep)
    floor = floor_of(scene)
    water = water_of(scene)
    add_floor(spec, floor, scene.world.floor_texture)
    for index, wall in enumerate(scene.world.walls):
        add_wall(spec, index, wall)
    for index, marker in enumerate(scene.markers):
        add_marker(spec, index, marker)
    objects = [
        add_object(spec, object_id, scene.object_types[p.type_name], p)
        for object_id, p in enumerate(scene.objects, start=1)
    ]
    robots = [
        add_robot(spec, robot_id, scene.robot_types[p.type_name], p, scene.settings)
        for robot_id, p in enumerate(scene.robots, start=1)
    ]
    world = PhysicsWorld(spec, water)
    for thing in objects + robots:
        thing.bind(world)
    floating = []
    if water is not None:
        for thing in objects:
            if thing.type.buoyancy > 0 and not thing.fixed:
                floating.append(_floating(world, thing))
    for forces in floating:
        forces.bind(world)
    return BuiltWorld(world, floor, water, robots, objects, floating)


def _check_triangles(scene: Scene) -> None:
    """Refuse, at the placement that passes it, a scene whose models are too detailed together."""
    total = 0
    placements = [(p, scene.object_types[p.type_name]) for p in scene.objects] + [
        (p, scene.robot_types[p.type_name]) for p in scene.robots
    ]
    for placement, kind in placements:
        mesh = model_mesh(kind.model)
        if mesh is None:
            continue
        total += sum(len(part.triangles) for part in mesh.parts)
        if total > MAX_SCENE_TRIANGLES:
            times = sum(1 for p, k in placements if k.model == kind.model)
            where = placement.location or Location(scene.source or "the scene")
            raise SceneError(
                [
                    Diagnostic(
                        "error",
                        where,
                        f"the scene's models have more than {MAX_SCENE_TRIANGLES} "
                        f"triangles together, the limit for a scene: {kind.model} is placed "
                        f"{times} time(s); use a simpler model or fewer of them",
                        "limit",
                    )
                ]
            )


def _floating(world: PhysicsWorld, thing: SceneObject) -> WaterForces:
    """The water's pull on an object, over the height its geoms span (object frame)."""
    model = world.model
    lows, highs = [], []
    for geom in thing.geoms:
        reach = model.geom_rbound[geom]
        lows.append(model.geom_pos[geom][2] - reach)
        highs.append(model.geom_pos[geom][2] + reach)
    low, high = min(lows), max(highs)
    centre = (0.0, 0.0, (low + high) / 2)
    return object_water_forces(thing.body, thing.type.buoyancy, high - low, centre)
