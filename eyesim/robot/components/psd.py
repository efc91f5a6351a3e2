"""PSD infrared distance sensors: one ray cast from the sensor's pose on the robot."""

from __future__ import annotations

import math

from eyesim.physics.units import mm, to_mm
from eyesim.robot.component import Component
from eyesim.scene.description import PsdSpec

MAX_RANGE_MM = 9999  # what PSDGet returns when nothing is within range


class PsdSensor(Component):
    kind = "psd"

    def __init__(self, spec: PsdSpec, robot):
        self.spec = spec
        self.robot = robot
        self.local = (mm(spec.x), mm(spec.y), mm(spec.z))
        heading, pitch = math.radians(spec.heading), math.radians(spec.pitch)
        self.local_direction = (math.cos(pitch) * math.cos(heading), math.cos(pitch) * math.sin(heading),
                                math.sin(pitch))

    @property
    def id(self) -> int:
        return self.spec.id

    def distance_mm(self) -> int:
        """Distance to the first thing the beam hits (walls, objects, other robots; not the
        robot's own body), rounded to mm; MAX_RANGE_MM when nothing is in range."""
        data = self.world.data
        rotation = data.xmat[self.robot.body].reshape(3, 3)
        origin = data.xpos[self.robot.body] + rotation @ self.local
        direction = rotation @ self.local_direction
        hit = self.world.ray(origin, direction, self.robot.body)
        if hit is None:
            return MAX_RANGE_MM
        return min(MAX_RANGE_MM, int(round(to_mm(hit))))


def create(context) -> list[Component]:
    return [PsdSensor(spec, context.robot) for spec in context.robot_type.psds]
