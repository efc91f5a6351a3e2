"""The MuJoCo world of one scene: model building from the scene description, stepping, poses, rays."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from eyesim.physics.units import mm, quat_yaw, yaw_quat
from eyesim.scene.description import Scene, Wall

FLOOR_MARGIN = 0.5  # m of floor beyond the walls' extent when a world gives no floor size
DEFAULT_FLOOR = 2.0  # m, floor side for a world with neither a size nor walls


@dataclass(frozen=True)
class Floor:
    width: float  # m along x
    height: float  # m along y


def floor_of(scene: Scene) -> Floor:
    """The floor's size in metres: as given, else the walls' extent plus a margin."""
    world = scene.world
    if world.floor_width and world.floor_height:
        return Floor(mm(world.floor_width), mm(world.floor_height))
    if world.walls:
        xs = [v for w in world.walls for v in (w.x1, w.x2)]
        ys = [v for w in world.walls for v in (w.y1, w.y2)]
        return Floor(mm(max(xs)) + FLOOR_MARGIN, mm(max(ys)) + FLOOR_MARGIN)
    return Floor(DEFAULT_FLOOR, DEFAULT_FLOOR)


def rgba(color, alpha: float = 1.0) -> list[float]:
    return [color[0] / 255.0, color[1] / 255.0, color[2] / 255.0, alpha]


def new_spec(timestep: float) -> mujoco.MjSpec:
    spec = mujoco.MjSpec()
    spec.modelname = "eyesim"
    spec.option.timestep = timestep
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    # Elliptic friction cones with a high impedance ratio make rolling contacts nearly slip-free,
    # so wheel odometry matches the ground truth the way it does on a real robot on a good floor.
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.option.impratio = 10
    return spec


def add_floor(spec: mujoco.MjSpec, floor: Floor) -> None:
    spec.worldbody.add_geom(
        name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE,
        size=[floor.width / 2, floor.height / 2, 0.05],
        pos=[floor.width / 2, floor.height / 2, 0.0],
        rgba=[0.82, 0.82, 0.78, 1.0], friction=[1.0, 0.005, 0.0001])


def add_wall(spec: mujoco.MjSpec, index: int, wall: Wall) -> None:
    x1, y1, x2, y2 = mm(wall.x1), mm(wall.y1), mm(wall.x2), mm(wall.y2)
    length = math.hypot(x2 - x1, y2 - y1)
    thickness = max(mm(wall.thickness), 0.002)
    height = max(mm(wall.height), 0.002)
    # A wall's length includes half its thickness at both ends so corners close.
    spec.worldbody.add_geom(
        name=f"wall{index}", type=mujoco.mjtGeom.mjGEOM_BOX,
        size=[(length + thickness) / 2, thickness / 2, height / 2],
        pos=[(x1 + x2) / 2, (y1 + y2) / 2, height / 2],
        quat=yaw_quat(math.atan2(y2 - y1, x2 - x1)),
        rgba=rgba(wall.color), friction=[0.6, 0.005, 0.0001])


class PhysicsWorld:
    """Compiled model + state. Bodies are addressed by name; poses in SI units."""

    def __init__(self, spec: mujoco.MjSpec):
        self.model = spec.compile()
        self.data = mujoco.MjData(self.model)
        mujoco.mj_forward(self.model, self.data)

    def step(self) -> None:
        mujoco.mj_step(self.model, self.data)

    def reset(self) -> None:
        mujoco.mj_resetData(self.model, self.data)
        mujoco.mj_forward(self.model, self.data)

    @property
    def time(self) -> float:
        return self.data.time

    def body_id(self, name: str) -> int:
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, name)

    def joint_id(self, name: str) -> int:
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, name)

    def actuator_id(self, name: str) -> int:
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, name)

    def pose(self, body: int) -> tuple[float, float, float, float]:
        """(x, y, z, yaw) of a body in metres and radians."""
        pos = self.data.xpos[body]
        return float(pos[0]), float(pos[1]), float(pos[2]), quat_yaw(self.data.xquat[body])

    def set_free_pose(self, body: int, x: float, y: float, z: float, yaw: float) -> None:
        """Teleport a body on a free joint; it comes to rest (zero velocity)."""
        joint = self.model.body_jntadr[body]
        qadr = self.model.jnt_qposadr[joint]
        vadr = self.model.jnt_dofadr[joint]
        self.data.qpos[qadr:qadr + 3] = (x, y, z)
        self.data.qpos[qadr + 3:qadr + 7] = yaw_quat(yaw)
        self.data.qvel[vadr:vadr + 6] = 0.0
        mujoco.mj_forward(self.model, self.data)

    def ray(self, origin, direction, exclude_body: int) -> float | None:
        """Distance (m) along a unit direction to the first geom hit, ignoring one body; None = no hit."""
        geomid = np.zeros(1, dtype=np.int32)
        dist = mujoco.mj_ray(self.model, self.data, np.asarray(origin, dtype=np.float64),
                             np.asarray(direction, dtype=np.float64), None, 1, exclude_body, geomid)
        return None if dist < 0 else float(dist)
