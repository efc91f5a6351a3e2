"""The MuJoCo world of one scene: the static parts (floor, walls, markers, shapes), stepping, poses, rays."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from eyesim.physics.units import mm, quat_yaw, yaw_quat
from eyesim.physics.visual_mesh import RAY_GROUPS
from eyesim.scene.description import Collider, Marker, Scene, Wall

FLOOR_MARGIN = 0.5  # m of floor beyond the walls' extent when a world gives no floor size
DEFAULT_FLOOR = 2.0  # m, floor side for a world with neither a size nor walls
FLOOR_FRICTION = 1.0
MARKER_RADIUS = 0.025  # m, as the viewer draws them
MARKER_THICKNESS = 0.0005  # m: flat on the floor, only there to be seen (by cameras)
# MuJoCo's arena (contacts, constraints and its working memory) is sized from the scene: its own
# default grows with the square of the bodies (1.8 GB for 1000 cans, 6.4 GB for 2000), which
# can fail to allocate. A contact with its constraints takes about 3 kB (measured), so this is
# room for about 30 contacts per body; bodies start apart (scene/placement.py), so a scene
# that runs out has piled things up, and MuJoCo then drops contacts with a warning.
ARENA_BASE = 16 * 1024 * 1024  # bytes: the model's own working memory and a few contacts
ARENA_PER_BODY = 96 * 1024  # bytes


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


def add_floor(spec: mujoco.MjSpec, floor: Floor, texture: str | None = None) -> None:
    """The floor plane; with `texture` (an image file) stretched once over it, its top edge north."""
    material = _floor_material(spec, texture) if texture else ""
    spec.worldbody.add_geom(
        name="floor",
        type=mujoco.mjtGeom.mjGEOM_PLANE,
        size=[floor.width / 2, floor.height / 2, 0.05],
        pos=[floor.width / 2, floor.height / 2, 0.0],
        rgba=[1.0, 1.0, 1.0, 1.0] if material else [0.82, 0.82, 0.78, 1.0],
        friction=[FLOOR_FRICTION, 0.005, 0.0001],
        material=material,
    )


def _floor_material(spec: mujoco.MjSpec, path: str) -> str:
    """A material with the image as its texture; "" when the image cannot be read (the floor
    then keeps its plain colour, as the loader already warned about a missing file)."""
    from PIL import Image, UnidentifiedImageError

    try:
        with Image.open(path) as image:
            pixels = np.asarray(image.convert("RGB"))
    except (OSError, UnidentifiedImageError):
        return ""
    height, width = pixels.shape[:2]
    # MuJoCo maps the first texture row to the plane's +y edge, so the image's top row lies north
    # as it is (tests/parts/camera/test_camera.py looks at it through a camera).
    texture = spec.add_texture(
        name="floor", type=mujoco.mjtTexture.mjTEXTURE_2D, width=width, height=height, nchannel=3
    )
    texture.data = np.ascontiguousarray(pixels).tobytes()
    material = spec.add_material(name="floor", texuniform=False, texrepeat=[1, 1])
    material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = "floor"
    return "floor"


def add_wall(spec: mujoco.MjSpec, index: int, wall: Wall) -> None:
    x1, y1, x2, y2 = mm(wall.x1), mm(wall.y1), mm(wall.x2), mm(wall.y2)
    length = math.hypot(x2 - x1, y2 - y1)
    thickness = max(mm(wall.thickness), 0.002)
    height = max(mm(wall.height), 0.002)
    # A wall's length includes half its thickness at both ends so corners close.
    spec.worldbody.add_geom(
        name=f"wall{index}",
        type=mujoco.mjtGeom.mjGEOM_BOX,
        size=[(length + thickness) / 2, thickness / 2, height / 2],
        pos=[(x1 + x2) / 2, (y1 + y2) / 2, height / 2],
        quat=yaw_quat(math.atan2(y2 - y1, x2 - x1)),
        rgba=rgba(wall.color),
        friction=[0.6, 0.005, 0.0001],
    )


def add_marker(spec: mujoco.MjSpec, index: int, marker: Marker) -> None:
    """A coloured disc on the floor; it has no collision bits (nothing bumps into a marker)."""
    r, g, b, a = marker.color
    spec.worldbody.add_geom(
        name=f"marker{index}",
        type=mujoco.mjtGeom.mjGEOM_CYLINDER,
        size=[MARKER_RADIUS, MARKER_THICKNESS / 2, 0],
        pos=[mm(marker.x), mm(marker.y), MARKER_THICKNESS / 2],
        rgba=[r / 255, g / 255, b / 255, a / 255],
        contype=0,
        conaffinity=0,
    )


def collider_volume(collider: Collider) -> float:
    """Volume in m^3 of a collider (sizes in mm)."""
    size = [mm(v) for v in collider.size]
    if collider.kind == "box":
        return size[0] * size[1] * size[2]
    if collider.kind == "sphere":
        return 4 / 3 * math.pi * size[0] ** 3
    radius, length = size[0], size[1]
    if collider.kind == "capsule":  # length includes both caps
        return math.pi * radius**2 * max(length - 2 * radius, 0.0) + 4 / 3 * math.pi * radius**3
    return math.pi * radius**2 * length


AXIS_QUATS = {
    "z": [1.0, 0.0, 0.0, 0.0],
    "x": [math.cos(math.pi / 4), 0.0, math.sin(math.pi / 4), 0.0],  # turns +z onto +x
    "y": [math.cos(math.pi / 4), -math.sin(math.pi / 4), 0.0, 0.0],
}  # turns +z onto +y


def add_collider(body: mujoco.MjsBody, name: str, collider: Collider, **attributes) -> mujoco.MjsGeom:
    """A geom of the collider's shape, size and place (mm in the body's frame)."""
    size = [mm(v) for v in collider.size]
    if collider.kind == "box":
        geom_type, geom_size = mujoco.mjtGeom.mjGEOM_BOX, [size[0] / 2, size[1] / 2, size[2] / 2]
    elif collider.kind == "sphere":
        geom_type, geom_size = mujoco.mjtGeom.mjGEOM_SPHERE, [size[0], 0.0, 0.0]
    elif collider.kind == "capsule":  # MuJoCo counts the half length without the caps
        geom_type, geom_size = mujoco.mjtGeom.mjGEOM_CAPSULE, [size[0], max(size[1] / 2 - size[0], 1e-4), 0.0]
    else:
        geom_type, geom_size = mujoco.mjtGeom.mjGEOM_CYLINDER, [size[0], size[1] / 2, 0.0]
    return body.add_geom(
        name=name,
        type=geom_type,
        size=geom_size,
        pos=[mm(v) for v in collider.center],
        quat=AXIS_QUATS[collider.axis],
        **attributes,
    )


class PhysicsWorld:
    """Compiled model + state. Bodies are addressed by name; poses in SI units. `water` is the
    scene's water volume (physics/water.py) or None."""

    def __init__(self, spec: mujoco.MjSpec, water=None):
        if spec.memory < 0:  # not chosen by the caller
            spec.memory = ARENA_BASE + ARENA_PER_BODY * len(spec.bodies)
        self.model = spec.compile()
        self.data = mujoco.MjData(self.model)
        self.water = water
        # Goes up whenever the state the sensors see changes (a step, a reset, a teleport): a
        # sensor may keep a reading made at the same state_version, it would come out the same.
        self.state_version = 0
        self.forward()

    def step(self) -> None:
        mujoco.mj_step(self.model, self.data)
        self.state_version += 1

    def forward(self) -> None:
        """Work out positions and contacts after the state was changed other than by a step."""
        mujoco.mj_forward(self.model, self.data)
        self.state_version += 1

    def reset(self) -> None:
        mujoco.mj_resetData(self.model, self.data)
        self.forward()

    @property
    def time(self) -> float:
        return self.data.time

    def body_id(self, name: str) -> int:
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, name)

    def joint_id(self, name: str) -> int:
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, name)

    def actuator_id(self, name: str) -> int:
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, name)

    def site_id(self, name: str) -> int:
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_SITE, name)

    def pose(self, body: int) -> tuple[float, float, float, float]:
        """(x, y, z, yaw) of a body in metres and radians."""
        pos = self.data.xpos[body]
        return float(pos[0]), float(pos[1]), float(pos[2]), quat_yaw(self.data.xquat[body])

    def set_free_pose(self, body: int, x: float, y: float, z: float, yaw: float) -> None:
        """Teleport a body on a free joint; it comes to rest (zero velocity)."""
        joint = self.model.body_jntadr[body]
        qadr = self.model.jnt_qposadr[joint]
        vadr = self.model.jnt_dofadr[joint]
        self.data.qpos[qadr : qadr + 3] = (x, y, z)
        self.data.qpos[qadr + 3 : qadr + 7] = yaw_quat(yaw)
        self.data.qvel[vadr : vadr + 6] = 0.0
        self.forward()

    def ray(self, origin, direction, exclude_body: int) -> float | None:
        """Distance (m) along a unit direction to the first geom hit, ignoring one body; None = no hit."""
        geomid = np.zeros(1, dtype=np.int32)
        dist = mujoco.mj_ray(
            self.model,
            self.data,
            np.asarray(origin, dtype=np.float64),
            np.asarray(direction, dtype=np.float64),
            RAY_GROUPS,
            1,
            exclude_body,
            geomid,
        )
        return None if dist < 0 else float(dist)
