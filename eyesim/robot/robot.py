"""The robot entity: identity, its chassis body and its components."""

from __future__ import annotations

import math
from typing import TypeVar

from eyesim.physics.units import to_mm
from eyesim.physics.world import PhysicsWorld
from eyesim.robot.component import Component
from eyesim.scene.description import RobotPlacement, RobotType

C = TypeVar("C", bound=Component)


class Robot:
    """A robot in the simulation. `id` is its 1-based position in the scene's robot list."""

    def __init__(self, robot_id: int, robot_type: RobotType, placement: RobotPlacement, body_name: str):
        self.id = robot_id
        self.type = robot_type
        self.name = robot_type.name
        self.placement = placement
        self.body_name = body_name
        self.components: list[Component] = []
        self.world: PhysicsWorld | None = None
        self.body = -1

    def bind(self, world: PhysicsWorld) -> None:
        self.world = world
        self.body = world.body_id(self.body_name)
        for component in self.components:
            component.bind(world)

    def component(self, cls: type[C]) -> C | None:
        """The robot's first component of a class, or None when it has none."""
        for component in self.components:
            if isinstance(component, cls):
                return component
        return None

    def components_of(self, cls: type[C]) -> list[C]:
        return [c for c in self.components if isinstance(c, cls)]

    def pose(self) -> tuple[float, float, float, float]:
        """True pose: x, y, z in metres (z of the floor-level origin), heading in radians."""
        return self.world.pose(self.body)

    def pose_mm(self) -> tuple[float, float, float, float]:
        """True pose in mm and degrees, as SIMGetRobot reports it."""
        x, y, z, yaw = self.pose()
        return to_mm(x), to_mm(y), to_mm(z), math.degrees(yaw)

    def set_pose(self, x: float, y: float, z: float, yaw: float) -> None:
        """Teleport the robot (like picking it up): its encoders and odometry don't notice."""
        self.world.set_free_pose(self.body, x, y, z, yaw)
