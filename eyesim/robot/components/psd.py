"""PSD infrared distance sensors: one ray cast from the sensor's pose on the robot."""

from __future__ import annotations

import math

import mujoco
import numpy as np

from eyesim.physics.units import mm, to_mm
from eyesim.robot.component import Component
from eyesim.scene.description import PsdSpec

MAX_RANGE_MM = 9999  # what PSDGet returns when nothing is within range


class PsdSensor(Component):
    """The sensor is a MuJoCo site on the chassis whose x axis is the beam, so MuJoCo keeps its
    world pose up to date and a reading is a single ray cast."""

    kind = "psd"

    def __init__(self, spec: PsdSpec, context):
        self.spec = spec
        self.robot = context.robot
        self.site_name = f"{context.prefix}/psd{spec.id}"
        context.body.add_site(name=self.site_name, pos=[mm(spec.x), mm(spec.y), mm(spec.z)],
                              quat=beam_quat(spec.heading, spec.pitch), size=[0.004, 0, 0], group=4)
        self._hit = np.zeros(1, dtype=np.int32)

    def bind(self, world) -> None:
        super().bind(world)
        self.site = mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_SITE, self.site_name)

    @property
    def id(self) -> int:
        return self.spec.id

    def distance_mm(self) -> int:
        """Distance to the first thing the beam hits (walls, objects, other robots; not the
        robot's own body), rounded to mm; MAX_RANGE_MM when nothing is in range."""
        data = self.world.data
        origin = data.site_xpos[self.site]
        direction = data.site_xmat[self.site][0::3].copy()  # the site's x axis
        hit = mujoco.mj_ray(self.world.model, data, origin, direction, None, 1, self.robot.body, self._hit)
        if hit < 0:
            return MAX_RANGE_MM
        return min(MAX_RANGE_MM, int(round(to_mm(hit))))


def beam_quat(heading: float, pitch: float) -> list[float]:
    """Quaternion turning +x into a beam `heading` degrees left and `pitch` degrees up:
    a rotation about z by the heading, then about the new y by minus the pitch."""
    h, p = math.radians(heading) / 2, -math.radians(pitch) / 2
    return [math.cos(h) * math.cos(p), -math.sin(h) * math.sin(p), math.cos(h) * math.sin(p),
            math.sin(h) * math.cos(p)]


def create(context) -> list[Component]:
    return [PsdSensor(spec, context) for spec in context.robot_type.psds]
