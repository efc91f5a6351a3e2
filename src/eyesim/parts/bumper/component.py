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
PRESSED_COLOR = [255, 143, 0]  # the viewer's mark on a pressed strip
LIFT = 0.002  # m the mark floats over the chassis top, so the top does not hide it
# The mark, from the middle of the strip's outer top edge: along that edge to both ends, down the
# face to its bottom corners and an arrowhead on the chassis top pointing out; in the strip's
# frame (outward, sideways, up) as multiples of its half depth, half width and half height.
MARK_ENDS = np.array([[1, -1, 1], [1, 1, 1], [1, -1, -1], [1, 1, -1], [1, -0.5, 1], [1, 0.5, 1]], dtype=float)
ARROW_BACK = 0.6  # of the half width: how far in from the edge the arrowhead's ends lie


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

    # -- how it shows itself (robot/component.py) --------------------------------------------------
    def overlay(self) -> list[dict]:
        """While pressed: a mark on the strip's outer face and on the chassis top by it (MARK_ENDS)."""
        if not self.pressed():
            return []
        data = self.world.data
        position, rotation = data.geom_xpos[self.geom], data.geom_xmat[self.geom].reshape(3, 3)
        half = self.world.model.geom_size[self.geom]
        local = MARK_ENDS * half
        local[4:, 0] -= ARROW_BACK * half[1]
        local[local[:, 2] > 0, 2] += LIFT
        origin = position + rotation @ [half[0], 0.0, half[2] + LIFT]
        return [
            {
                "kind": "bumper",
                "id": self.id,
                "color": PRESSED_COLOR,
                "origin": origin,
                "ends": (position + local @ rotation.T).ravel(),
            }
        ]

    def signals(self) -> dict[str, tuple[float, str]]:
        """bumper.<id>: 1 while pressed, 0 while free."""
        return {f"bumper.{self.id}": (1 if self.pressed() else 0, "pressed")}


def create(context) -> list[Component]:
    return [Bumper(spec, context) for spec in context.robot_type.bumpers]
