"""Buoyancy and drag of a robot's hull in the scene's water (its `buoyancy` and `drag` lines)."""

from __future__ import annotations

from functools import partial

from eyesim.parts.water.declaration import BuoyancySpec
from eyesim.physics.units import mm
from eyesim.physics.water import DENSITY, WaterForces
from eyesim.robot.component import Component
from eyesim.scene.parts.body import hull_centroid


class Buoyancy(Component):
    """The hull is the robot's height above its origin; buoyancy acts at the centre of buoyancy,
    drag at the middle of the submerged hull. Out of the water (or in a scene without water)
    nothing acts and the robot simply falls."""

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
        self.height = height
        self.start_depth = mm(robot_type.start_depth) if robot_type.start_depth is not None else None
        self.forces_on = partial(  # the forces on the robot's body, once it is bound
            WaterForces,
            volume=spec.volume / 1000.0,
            buoyancy_centre=(mm(spec.x), mm(spec.y), mm(spec.z)),
            hull_centre=(0.0, 0.0, height / 2),
            height=height,
            drag=(drag.x, drag.y, drag.z) if drag else (0.0, 0.0, 0.0),
            rotational_drag=drag.rotation if drag else 0.0,
            # drag acts on the hull where it is: the middle of its colliders
            pressure_centre=tuple(mm(v) for v in hull_centroid(robot_type)),
        )

    def bind(self, world) -> None:
        super().bind(world)
        self.forces = self.forces_on(self.robot.body)
        self.forces.bind(world)

    def reset(self) -> None:
        self.world.data.xfrc_applied[self.robot.body] = 0.0
        if self.world.water is None or self.robot.mounted:
            return
        if self.start_depth is not None:
            self._start_at(max(0.0, self.world.water.surface - self.start_depth - self.height))
        elif self.afloat_draft is not None:
            self._start_at(self.world.water.surface - self.afloat_draft)

    def _start_at(self, height: float) -> None:
        """The placement gives no height: a robot whose type gives a start depth starts with its
        hull's top that far below the surface (on the pool floor if the pool is shallower); one
        that floats starts where it floats, at the surface, rather than on the pool floor."""
        model, data = self.world.model, self.world.data
        joint = model.body_jntadr[self.robot.body]
        data.qpos[model.jnt_qposadr[joint] + 2] = height
        self.world.forward()

    def before_step(self, dt: float) -> None:
        if self.world.water is not None:
            self.forces.apply()


def create(context) -> list[Component]:
    robot_type = context.robot_type
    water = (robot_type.buoyancy, robot_type.drag, robot_type.start_depth)
    return [Buoyancy(context)] if any(part is not None for part in water) else []
