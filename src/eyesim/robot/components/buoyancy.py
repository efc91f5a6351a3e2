"""Buoyancy and drag of a robot's hull in the scene's water (its `buoyancy` and `drag` lines)."""

from __future__ import annotations

from eyesim.physics.units import mm
from eyesim.physics.water import DENSITY, WaterForces
from eyesim.robot.component import Component
from eyesim.scene.description import BuoyancySpec


class Buoyancy(Component):
    """The hull is the robot's height above its origin; buoyancy acts at the centre of buoyancy.
    Out of the water (or in a scene without water) nothing acts and the robot simply falls."""

    def __init__(self, context):
        robot_type = context.robot_type
        spec = robot_type.buoyancy or BuoyancySpec(0.0)
        drag = robot_type.drag
        height = mm(robot_type.height)
        self.robot = context.robot
        # The part of the hull under water when afloat: what displaces the robot's mass, if less
        # than all of it (then the robot floats).
        displaced = (spec.volume / 1000.0) * DENSITY
        self.afloat_draft = height * robot_type.mass / displaced if displaced > robot_type.mass else None
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
        if self.world.water is not None and self.afloat_draft is not None and not self.robot.mounted:
            self._start_afloat()

    def _start_afloat(self) -> None:
        """A robot that floats starts where it floats, at the surface, rather than on the pool
        floor: the placement gives no height, and a submarine starts afloat in EyeSim."""
        model, data = self.world.model, self.world.data
        joint = model.body_jntadr[self.robot.body]
        data.qpos[model.jnt_qposadr[joint] + 2] = self.world.water.surface - self.afloat_draft
        self.world.forward()

    def before_step(self, dt: float) -> None:
        if self.world.water is not None:
            self.forces.apply()


def create(context) -> list[Component]:
    robot_type = context.robot_type
    return [Buoyancy(context)] if robot_type.buoyancy is not None or robot_type.drag is not None else []
