"""A PSD in the simulation: one ray cast from the sensor's pose on the robot."""

from __future__ import annotations

import dataclasses
import math

import mujoco
import numpy as np

from eyesim.parts.psd.declaration import PsdSpec
from eyesim.physics.units import mm, to_mm
from eyesim.physics.visual_mesh import RAY_GROUPS
from eyesim.protocol import generated as g
from eyesim.robot.component import Component

MAX_RANGE_MM = 9999  # what PSDGet returns when nothing is within range
# PSDGetRaw's sensor curve, a 10-bit reading falling with distance like a Sharp IR sensor's
# output voltage: raw = RAW_SCALE / (mm + RAW_OFFSET), so 0 mm -> 1023, 100 mm -> 512, 1 m -> 93.
RAW_SCALE = 102300
RAW_OFFSET = 100


def raw_value(distance_mm: int) -> int:
    """The raw reading of a sensor that measures `distance_mm` (see RAW_SCALE)."""
    return min(1023, round(RAW_SCALE / (max(0, distance_mm) + RAW_OFFSET)))


class PsdSensor(Component):
    """The sensor is a MuJoCo site on the chassis whose x axis is the beam, so MuJoCo keeps its
    world pose up to date and a reading is a single ray cast."""

    def __init__(self, spec: PsdSpec, context):
        self.spec = spec
        self.robot = context.robot
        self.site_name = f"{context.prefix}/psd{spec.id}"
        context.body.add_site(
            name=self.site_name,
            pos=[mm(spec.x), mm(spec.y), mm(spec.z)],
            quat=beam_quat(spec.heading, spec.pitch),
            size=[0.004, 0, 0],
            group=4,
        )
        self.noise_mm = context.settings.psd_noise
        # One generator per sensor, seeded by the scene's seed and the sensor's identity: the
        # noise a sensor sees does not depend on what other sensors or robots read.
        self._seed = (context.settings.seed, context.robot.id, spec.id)
        self._hit = np.zeros(1, dtype=np.int32)
        # (world.state_version, exact hit in m or None) of the last cast: a program polling faster
        # than the physics step reads the same state, and the cast would come out the same.
        self._cached: tuple[int, float | None] | None = None

    def bind(self, world) -> None:
        super().bind(world)
        self.site = mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_SITE, self.site_name)

    def reset(self) -> None:
        self._cached = None
        self.random = np.random.default_rng(self._seed) if self.noise_mm > 0 else None

    def set_noise(self, noise_mm: float, seed: int) -> None:
        """New scene settings while running (the viewer's settings): the noise restarts from the seed."""
        self.noise_mm = noise_mm
        self._seed = (seed, self.robot.id, self.spec.id)
        self.reset()

    @property
    def id(self) -> int:
        return self.spec.id

    def beam(self) -> tuple[np.ndarray, np.ndarray, float | None]:
        """The beam's origin and unit direction (world) and the exact distance in metres to the
        first thing it hits (walls, objects, other robots; not the robot's own body), or None."""
        data = self.world.data
        origin = data.site_xpos[self.site]
        direction = data.site_xmat[self.site][0::3].copy()  # the site's x axis
        hit = mujoco.mj_ray(self.world.model, data, origin, direction, RAY_GROUPS, 1, self.robot.body, self._hit)
        return origin, direction, (hit if hit >= 0 else None)

    def distance_mm(self) -> int:
        """What PSDGet reports: the distance rounded to mm, with the scene's noise if it has any;
        MAX_RANGE_MM when nothing is in range. The noise is drawn anew for every reading."""
        hit = self._exact_hit()
        if hit is None:
            return MAX_RANGE_MM
        distance = to_mm(hit)
        if self.random is not None:
            distance += self.random.normal(0.0, self.noise_mm)
        return max(0, min(MAX_RANGE_MM, int(round(distance))))

    def _exact_hit(self) -> float | None:
        """The beam's hit distance in the world's state of the moment, cast once per state."""
        version = self.world.state_version
        cached = self._cached
        if cached is None or cached[0] != version:
            cached = self._cached = (version, self.beam()[2])
        return cached[1]

    def raw(self) -> int:
        """What PSDGetRaw reports: the reading's distance through the sensor curve."""
        return raw_value(self.distance_mm())

    # -- how it shows itself (robot/component.py) --------------------------------------------------
    recorded_ops = frozenset((g.OP_PSD_GET, g.OP_PSD_GET_RAW))

    def overlay(self) -> list[dict]:
        """Its beam, to what it hits or to the end of its range."""
        origin, direction, hit = self.beam()
        end = origin + direction * (hit if hit is not None else MAX_RANGE_MM / 1000)
        return [{"kind": "psd", "psd": self.id, "origin": origin, "ends": end}]

    def recorded(self, op: int, args: tuple, reply: tuple) -> tuple[str, object] | None:
        """The readings the program asked for of this sensor (PSDGet, PSDGetRaw)."""
        if args[0] != self.id:
            return None
        return "psd", {"psd": self.id, ("distance_mm" if op == g.OP_PSD_GET else "raw"): reply[0]}

    def editor_view(self) -> dict:
        origin, direction, hit = self.beam()
        return {
            "psds": [
                {
                    "id": self.id,
                    "name": self.spec.name,
                    "origin": origin,
                    "direction": direction,
                    "hit": None if hit is None else round(float(hit), 4),
                }
            ]
        }

    def readings(self) -> dict:
        return {"psd": {str(self.id): self.distance_mm()}}

    def settings_changed(self, settings) -> None:
        self.set_noise(settings.psd_noise, settings.seed)


def beam_quat(heading: float, pitch: float) -> list[float]:
    """Quaternion turning +x into a beam `heading` degrees left and `pitch` degrees up:
    a rotation about z by the heading, then about the new y by minus the pitch."""
    h, p = math.radians(heading) / 2, -math.radians(pitch) / 2
    return [math.cos(h) * math.cos(p), -math.sin(h) * math.sin(p), math.cos(h) * math.sin(p), math.sin(h) * math.cos(p)]


def eyesim6_numbering(psds: tuple[PsdSpec, ...]) -> tuple[PsdSpec, ...]:
    """The sensors as EyeSim 6 programs number them (scene setting EYESIM6PSD): LEFT 1, FRONT 2.
    Only a robot numbered the RoBIOS-7 way, PSD_FRONT 1 and PSD_LEFT 2, changes: those two trade
    ids (RIGHT 3 and BACK 4 are the same in both); other sensors keep theirs."""
    names = {spec.id: spec.name.upper() for spec in psds}
    if names.get(1) != "PSD_FRONT" or names.get(2) != "PSD_LEFT":
        return psds
    return tuple(dataclasses.replace(spec, id={1: 2, 2: 1}.get(spec.id, spec.id)) for spec in psds)


def create(context) -> list[Component]:
    psds = context.robot_type.psds
    if context.settings.eyesim6_psd:
        psds = eyesim6_numbering(psds)
    return [PsdSensor(spec, context) for spec in psds]
