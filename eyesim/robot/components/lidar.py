"""Scanning lidar: one batched ray cast per scan, in a plane through the robot's top centre."""

from __future__ import annotations

import math

import mujoco
import numpy as np

from eyesim.physics.units import mm
from eyesim.physics.visual_mesh import RAY_GROUPS
from eyesim.robot.component import Component
from eyesim.scene.description import LidarSpec

MAX_RANGE_MM = 9999  # what a beam that hits nothing within range reports
MOUNT_ABOVE_TOP = 10.0  # mm the scanner's centre sits above the chassis top
MAX_POINTS = 3600
DEFAULT = LidarSpec(points=360, tilt=0.0)  # the scanner of a robot without a `lidar` line


class LidarScanner(Component):
    """Beam i of a scan points (i - points/2) * range/points degrees clockwise from straight
    ahead: index points/2 looks ahead and the indices grow clockwise seen from above (for the
    default 360 points over 360 degrees: 0 behind, 90 left, 180 ahead, 270 right). The scan
    plane is tilted about the robot's y axis: a positive tilt lowers the front beams and
    raises the back ones."""

    kind = "lidar"

    def __init__(self, spec: LidarSpec, context):
        self.spec = spec
        self.robot = context.robot
        self.mount = np.array([0.0, 0.0, mm(context.robot_type.height + MOUNT_ABOVE_TOP)])
        self.last_scan: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None

    def reset(self) -> None:
        self.configure(360, self.spec.tilt, self.spec.points)
        self.last_scan = None

    def configure(self, field_deg: float, tilt_deg: float, points: int) -> None:
        """Field of view (degrees, centred ahead), tilt (degrees, positive = front down), beam count."""
        self.field, self.tilt, self.points = field_deg, tilt_deg, points
        clockwise = np.radians((np.arange(points) - points // 2) * field_deg / points)
        tilt = math.radians(tilt_deg)
        # Level beam (cos a, -sin a, 0) for a clockwise angle a, then turned about y by the tilt.
        self._local = np.stack([np.cos(clockwise) * math.cos(tilt), -np.sin(clockwise),
                                -np.cos(clockwise) * math.sin(tilt)], axis=1)
        self._geom = np.zeros(points, dtype=np.int32)
        self._dist = np.zeros(points, dtype=np.float64)

    def scan(self) -> np.ndarray:
        """Distances in mm (int32), MAX_RANGE_MM where a beam hits nothing in range."""
        model, data = self.world.model, self.world.data
        rotation = data.xmat[self.robot.body].reshape(3, 3)
        origin = data.xpos[self.robot.body] + rotation @ self.mount
        directions = self._local @ rotation.T
        mujoco.mj_multiRay(model, data, origin, directions.ravel(), RAY_GROUPS, 1, self.robot.body,
                           self._geom, self._dist, None, self.points, mm(MAX_RANGE_MM))
        self._look_past_own_parts(origin, directions)
        within = (self._dist >= 0) & (self._dist < mm(MAX_RANGE_MM))
        distances = np.where(within, np.rint(self._dist * 1000.0), MAX_RANGE_MM).astype(np.int32)
        self.last_scan = (origin.copy(), directions, distances)
        return distances

    def _look_past_own_parts(self, origin: np.ndarray, directions: np.ndarray) -> None:
        """Beams that hit one of the robot's own moving parts (a wheel, an arm link: bodies other
        than the chassis, which the ray cast already ignores) continue past it."""
        model, data = self.world.model, self.world.data
        hit = self._geom >= 0
        own = np.flatnonzero(hit & (model.body_rootid[model.geom_bodyid[np.where(hit, self._geom, 0)]]
                                    == self.robot.body))
        geom = np.zeros(1, dtype=np.int32)
        for i in own:
            travelled, part, segment = 0.0, self._geom[i], self._dist[i]
            while part >= 0 and model.body_rootid[model.geom_bodyid[part]] == self.robot.body:
                travelled += segment + 1e-6
                segment = mujoco.mj_ray(model, data, origin + directions[i] * travelled, directions[i], RAY_GROUPS, 1,
                                        model.geom_bodyid[part], geom)
                part = geom[0]
            self._geom[i], self._dist[i] = part, (travelled + segment if part >= 0 else -1.0)


def create(context) -> list[Component]:
    return [LidarScanner(context.robot_type.lidar or DEFAULT, context)]
