"""Scanning lidar: one batched ray cast per scan, in a plane through the robot's top centre."""

from __future__ import annotations

import math

import mujoco
import numpy as np

from eyesim.parts.lidar.declaration import LidarSpec
from eyesim.physics.units import mm
from eyesim.physics.visual_mesh import RAY_GROUPS
from eyesim.protocol import generated as g
from eyesim.robot.component import Component

MAX_RANGE_MM = 9999  # what a beam that hits nothing within range reports
MOUNT_ABOVE_TOP = 10.0  # mm the scanner's centre sits above the chassis top
MAX_POINTS = 3600
DEFAULT = LidarSpec(points=360, tilt=0.0)  # the scanner of a robot without a `lidar` line
# SIMLaserScan's beams (EyeSim 6): level, beam i at i degrees counter-clockwise from ahead.
_ccw = np.radians(np.arange(360))
LASER_SCAN_BEAMS = np.stack([np.cos(_ccw), np.sin(_ccw), np.zeros(360)], axis=1)


class LidarScanner(Component):
    """Beam i of a scan points (i - points/2) * range/points degrees clockwise from straight
    ahead: index points/2 looks ahead and the indices grow clockwise seen from above (for the
    default 360 points over 360 degrees: 0 behind, 90 left, 180 ahead, 270 right). The scan
    plane is tilted about the robot's y axis: a positive tilt lowers the front beams and
    raises the back ones."""

    noun = "lidar"

    def __init__(self, spec: LidarSpec, context):
        self.spec = spec
        self.robot = context.robot
        self.mount = np.array([0.0, 0.0, mm(context.robot_type.height + MOUNT_ABOVE_TOP)])
        self.last_scan: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
        # (world.state_version, beams, distances) of the last cast: a program polling faster than
        # the physics steps (2 ms) gets the same scan again without casting it again.
        self._cached: tuple[int, np.ndarray, np.ndarray] | None = None

    def bind(self, world) -> None:
        super().bind(world)
        model = world.model
        # Which geoms are the robot's own moving parts (wheels, arm links: the chassis is left
        # out by the ray cast itself); one more entry, False, for "hit nothing" (geom -1).
        own = model.body_rootid[model.geom_bodyid] == self.robot.body
        self._own_parts = np.append(own, False)

    def reset(self) -> None:
        self.configure(360, self.spec.tilt, self.spec.points)
        self.last_scan = None
        self._cached = None

    def configure(self, field_deg: float, tilt_deg: float, points: int) -> None:
        """Field of view (degrees, centred ahead), tilt (degrees, positive = front down), beam count."""
        self.field, self.tilt, self.points = field_deg, tilt_deg, points
        clockwise = np.radians((np.arange(points) - points // 2) * field_deg / points)
        tilt = math.radians(tilt_deg)
        # Level beam (cos a, -sin a, 0) for a clockwise angle a, then turned about y by the tilt.
        self._local = np.stack(
            [np.cos(clockwise) * math.cos(tilt), -np.sin(clockwise), -np.cos(clockwise) * math.sin(tilt)], axis=1
        )

    def scan(self) -> np.ndarray:
        """Distances in mm (int32), MAX_RANGE_MM where a beam hits nothing in range."""
        return self._cast(self._local)

    def laser_scan(self) -> np.ndarray:
        """EyeSim 6's SIMLaserScan: 360 level beams, index i at i degrees counter-clockwise from
        ahead, whatever configure() set (that stays for scan())."""
        return self._cast(LASER_SCAN_BEAMS)

    def _cast(self, local: np.ndarray) -> np.ndarray:
        """Distances in mm along beams given in the robot's frame (read-only: the same array comes
        back while the state is the same); the last scan, for the viewer."""
        cached = self._cached
        if cached is not None and cached[0] == self.world.state_version and cached[1] is local:
            return cached[2]
        model, data = self.world.model, self.world.data
        rotation = data.xmat[self.robot.body].reshape(3, 3)
        origin = data.xpos[self.robot.body] + rotation @ self.mount
        directions = local @ rotation.T
        geom = np.zeros(len(local), dtype=np.int32)
        dist = np.zeros(len(local), dtype=np.float64)
        mujoco.mj_multiRay(
            model,
            data,
            origin,
            directions.ravel(),
            RAY_GROUPS,
            1,
            self.robot.body,
            geom,
            dist,
            None,
            len(local),
            mm(MAX_RANGE_MM),
        )
        self._look_past_own_parts(origin, directions, geom, dist)
        within = (dist >= 0) & (dist < mm(MAX_RANGE_MM))
        distances = np.where(within, np.rint(dist * 1000.0), MAX_RANGE_MM).astype(np.int32)
        distances.flags.writeable = False
        self.last_scan = (origin.copy(), directions, distances)
        self._cached = (self.world.state_version, local, distances)
        return distances

    # -- how it shows itself (robot/component.py) --------------------------------------------------
    recorded_ops = frozenset((g.OP_LIDAR_GET,))

    def overlay(self) -> list[dict]:
        """The beams of the last scan a program took, to what each hit or to the end of its range."""
        if self.last_scan is None:
            return []
        origin, directions, distances = self.last_scan
        ends = origin + directions * (distances[:, None] / 1000.0)
        return [{"kind": "lidar", "origin": origin, "ends": ends.reshape(-1)}]

    def recorded(self, op: int, args: tuple, reply: tuple) -> tuple[str, object] | None:
        """A LIDARGet's scan as a foxglove.LaserScan: beams counter-clockwise from the first, in the
        robot's frame, the scan plane turned about y by the tilt."""
        distances_mm = reply[1]
        points = len(distances_mm)
        step = math.radians(self.field) / points
        start = (points // 2) * step  # beam 0 is the most counter-clockwise (docs/api/lidar.md)
        tilt = math.radians(self.tilt)
        return "lidar", {
            "pose": {
                "position": {"x": 0.0, "y": 0.0, "z": float(self.mount[2])},
                "orientation": {"x": 0.0, "y": math.sin(tilt / 2), "z": 0.0, "w": math.cos(tilt / 2)},
            },
            "start_angle": start,
            "end_angle": start - (points - 1) * step,
            "ranges": [d / 1000 for d in distances_mm],
            "intensities": [],
        }

    def editor_view(self) -> dict:
        """The scan plane: where the beams start and which way they go (a robot with a lidar line)."""
        if self.robot.type.lidar is None:
            return {}
        if self.last_scan is None:
            self.scan()  # sets last_scan
            assert self.last_scan is not None
        origin, directions, _ = self.last_scan
        return {"lidar": {"origin": origin, "directions": directions, "points": len(directions)}}

    def readings(self) -> dict:
        return {"lidar": self.scan().tolist()} if self.robot.type.lidar is not None else {}

    def _look_past_own_parts(
        self, origin: np.ndarray, directions: np.ndarray, geoms: np.ndarray, dists: np.ndarray
    ) -> None:
        """Beams that hit one of the robot's own moving parts (a wheel, an arm link: bodies other
        than the chassis, which the ray cast already ignores) continue past it."""
        own = np.flatnonzero(self._own_parts[geoms])
        if not len(own):
            return
        model, data = self.world.model, self.world.data
        geom = np.zeros(1, dtype=np.int32)
        for i in own:
            travelled, part, segment = 0.0, geoms[i], dists[i]
            while self._own_parts[part]:  # (-1, nothing hit, is the table's last entry: False)
                travelled += segment + 1e-6
                segment = mujoco.mj_ray(
                    model,
                    data,
                    origin + directions[i] * travelled,
                    directions[i],
                    RAY_GROUPS,
                    1,
                    model.geom_bodyid[part],
                    geom,
                )
                part = geom[0]
            geoms[i], dists[i] = part, (travelled + segment if part >= 0 else -1.0)


def create(context) -> list[Component]:
    return [LidarScanner(context.robot_type.lidar or DEFAULT, context)]
