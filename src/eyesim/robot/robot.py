"""The robot entity: identity, its chassis body, its components and the actuators they own."""

from __future__ import annotations

import math
from typing import TypeVar

from eyesim.physics.units import to_mm
from eyesim.physics.world import PhysicsWorld
from eyesim.robot.component import Component
from eyesim.scene.description import RobotPlacement, RobotType

C = TypeVar("C", bound=Component)


class MountedRobotError(Exception):
    """Raised when something tries to move a robot bolted to the floor."""


class Robot:
    """A robot in the simulation. `id` is its 1-based position in the scene's robot list.

    `part_names` are the bodies components added below the chassis (wheels, arm links, fingers),
    `shown_part_names` those the viewer draws on their own; `motors`, `encoders` and `servos` map
    RoBIOS numbers to the actuators of all components."""

    def __init__(
        self, robot_id: int, robot_type: RobotType, placement: RobotPlacement, body_name: str, mounted: bool = False
    ):
        self.id = robot_id
        self.type = robot_type
        self.name = robot_type.name
        self.placement = placement
        self.body_name = body_name
        self.mounted = mounted
        self.components: list[Component] = []  # complete once built (robot/build.py)
        self._of_class: dict[type, list] = {}  # components_of, looked up on every call of a handler
        self.part_names: list[str] = []
        self.shown_part_names: list[str] = []
        self.motors: dict = {}
        self.encoders: dict = {}
        self.servos: dict = {}
        self.world: PhysicsWorld | None = None
        self.body = -1

    def bind(self, world: PhysicsWorld) -> None:
        self.world = world
        self._of_class = {}  # the components are complete now
        self.body = world.body_id(self.body_name)
        self.shown_parts = [world.body_id(name) for name in self.shown_part_names]
        for component in self.components:
            component.bind(world)
            for numbered, table in ((self.motors, "motors"), (self.encoders, "encoders"), (self.servos, "servos")):
                for number, actuator in getattr(component, table, {}).items():
                    numbered.setdefault(number, actuator)

    def component(self, cls: type[C]) -> C | None:
        """The robot's first component of a class, or None when it has none."""
        found = self.components_of(cls)
        return found[0] if found else None

    def components_of(self, cls: type[C]) -> list[C]:
        found = self._of_class.get(cls)
        if found is None:
            found = self._of_class[cls] = [c for c in self.components if isinstance(c, cls)]
        return found

    def _bound(self) -> PhysicsWorld:
        if self.world is None:
            raise RuntimeError(f"robot {self.id} ({self.name}) is not in a world yet (bind it first)")
        return self.world

    def pose(self) -> tuple[float, float, float, float]:
        """True pose: x, y, z in metres (z of the floor-level origin), heading in radians."""
        return self._bound().pose(self.body)

    def pose_mm(self) -> tuple[float, float, float, float]:
        """True pose in mm and degrees, as SIMGetRobot reports it."""
        x, y, z, yaw = self.pose()
        return to_mm(x), to_mm(y), to_mm(z), math.degrees(yaw)

    def set_pose(self, x: float, y: float, z: float, yaw: float) -> None:
        """Teleport the robot (like picking it up): its encoders and odometry don't notice."""
        if self.mounted:
            raise MountedRobotError(f"robot {self.id} ({self.name}) is mounted on the floor and cannot be moved")
        self._bound().set_free_pose(self.body, x, y, z, yaw)
