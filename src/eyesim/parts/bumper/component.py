"""A bumper in the simulation: a thin box on the chassis that collides like the hull; it is pressed
while MuJoCo has a contact of that box with anything (a wall, an object, another robot)."""

from __future__ import annotations

import mujoco
import numpy as np

from eyesim.parts.bumper.declaration import BumperSpec
from eyesim.physics.units import mm, rad, yaw_quat
from eyesim.robot.component import Component
from eyesim.robot.components.digital_io import DigitalLines

DEPTH_MM = 10.0  # the strip's thickness: it reaches 5 mm out of the place the robot file gives
BOTTOM_MM = 15.0  # above the floor and the wheeled chassis' clearance: the floor never presses it
FRICTION = [0.4, 0.005, 0.0001]  # the hull's (robot/build.py): a bumper slides along a wall as the hull does


class Bumper(Component):
    noun = "bumper"

    def __init__(self, spec: BumperSpec, context):
        self.spec = spec
        height = max(context.robot_type.height - BOTTOM_MM, 10.0)
        self.geom_name = f"{context.prefix}/bumper{spec.id}"
        context.body.add_geom(
            name=self.geom_name,
            type=mujoco.mjtGeom.mjGEOM_BOX,
            size=[mm(DEPTH_MM / 2), mm(spec.width / 2), mm(height / 2)],
            pos=[mm(spec.x), mm(spec.y), mm(BOTTOM_MM + height / 2)],
            quat=yaw_quat(rad(spec.angle)),
            mass=0.0,
            friction=FRICTION,
            rgba=[0.1, 0.1, 0.1, 1],
        )
        self.robot = context.robot

    def bind(self, world) -> None:
        super().bind(world)
        self.geom = mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_GEOM, self.geom_name)
        self.robot.component(DigitalLines).wire(self.spec.line, f"bumper {self.spec.id}", self.level)

    @property
    def id(self) -> int:
        return self.spec.id

    def pressed(self) -> bool:
        """Whether the strip touches something in the world's state of the moment."""
        data = self.world.data
        return bool(np.any(data.contact.geom[: data.ncon] == self.geom))

    def level(self) -> int:
        """What its digital line reads: a switch to ground on a pulled-up line, 0 while pressed."""
        return 0 if self.pressed() else 1


def create(context) -> list[Component]:
    return [Bumper(spec, context) for spec in context.robot_type.bumpers]
