"""Buoyancy and drag of a robot's hull in the scene's water (its `buoyancy` and `drag` lines)."""

from __future__ import annotations

from eyesim.physics.units import mm
from eyesim.physics.water import WaterForces
from eyesim.robot.component import Component
from eyesim.scene.description import BuoyancySpec


class Buoyancy(Component):
    """The hull is the robot's height above its origin; buoyancy acts at the centre of buoyancy.
    Out of the water (or in a scene without water) nothing acts and the robot simply falls."""

    kind = "buoyancy"

    def __init__(self, context):
        robot_type = context.robot_type
        spec = robot_type.buoyancy or BuoyancySpec(0.0)
        drag = robot_type.drag
        height = mm(robot_type.height)
        self.robot = context.robot
        self.parameters = dict(volume=spec.volume / 1000.0, buoyancy_centre=(mm(spec.x), mm(spec.y), mm(spec.z)),
                               hull_centre=(0.0, 0.0, height / 2), height=height,
                               drag=(drag.x, drag.y, drag.z) if drag else (0.0, 0.0, 0.0),
                               rotational_drag=drag.rotation if drag else 0.0)

    def bind(self, world) -> None:
        super().bind(world)
        self.forces = WaterForces(self.robot.body, **self.parameters)
        self.forces.bind(world)

    def reset(self) -> None:
        self.world.data.xfrc_applied[self.robot.body] = 0.0

    def before_step(self, dt: float) -> None:
        if self.world.water is not None:
            self.forces.apply()


def create(context) -> list[Component]:
    robot_type = context.robot_type
    return [Buoyancy(context)] if robot_type.buoyancy is not None or robot_type.drag is not None else []
