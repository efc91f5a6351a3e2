"""Immutable scene description: what the scene files say, as frozen dataclasses.

Units are the files' own (millimetres, degrees, kilograms, 0-255 colour channels) so that text
and JSON convert into each other without loss; `physics/` converts to SI when it builds a model.
World frame: x east, y north, z up, origin at the floor's lower-left corner, headings in degrees
counter-clockwise from +x. Robot frame: x forward, y left, z up, origin at the robot's centre on
the floor. Object frame: the same axes, origin at the object's centre on the floor.

Every position below is already converted into these frames, whatever dialect the file used
(see docs/file-formats.md); the only exception is a robot's mesh placement (`model_offset`,
`model_rotation`), which stays in the mesh's own axes because it only concerns drawing the mesh.
`RobotType` and the specs of its parts (PsdSpec, CameraSpec, Collider ...) are declared by the
robot part kinds (parts/<kind>/declaration.py, scene/parts/), `Location` and `Diagnostic` by scene/diagnostics.py; all are
importable from here as well.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.parts.arm.declaration import ArmSpec, GripperSpec, JointSpec
from eyesim.parts.camera.declaration import CameraSpec
from eyesim.parts.lidar.declaration import LidarSpec
from eyesim.parts.psd.declaration import PsdSpec
from eyesim.parts.thrusters.declaration import ThrusterSpec
from eyesim.parts.water.declaration import BuoyancySpec, DragSpec
from eyesim.scene.diagnostics import Diagnostic, Location
from eyesim.scene.parts import RobotType
from eyesim.scene.parts.body import Collider
from eyesim.scene.parts.wheels import SteeringSpec, WheelSpec


@dataclass(frozen=True)
class Pose:
    """A pose on the floor: x, y in mm, phi in degrees (CCW from +x)."""

    x: float
    y: float
    phi: float = 0.0


@dataclass(frozen=True)
class Wall:
    """A straight wall segment in world coordinates (mm); colour as (r, g, b) 0-255."""

    x1: float
    y1: float
    x2: float
    y2: float
    thickness: float = 10.0
    height: float = 300.0
    color: tuple[int, int, int] = (200, 200, 200)


@dataclass(frozen=True)
class StartPosition:
    """A maze start letter: the letter as written and the pose it stands for."""

    letter: str
    pose: Pose


@dataclass(frozen=True)
class ObjectPlacement:
    """An object of a named type placed in the world.

    `type_name` is always a key of `Scene.object_types`. `friction` is the EyeSim 6 per-object
    friction value (`object x y phi friction model`), None when the file gives none.
    """

    type_name: str
    pose: Pose
    location: Location | None = None
    friction: float | None = None


@dataclass(frozen=True)
class Marker:
    """A coloured marker on the floor at (x, y) mm; colour (r, g, b, a) 0-255."""

    x: float
    y: float
    color: tuple[int, int, int, int] = (255, 0, 0, 255)


@dataclass(frozen=True)
class World:
    """The environment: floor, walls and what a .wld or .maz file places in it.

    Straight after parsing, `floor_texture` is the path as written in the file; a loaded scene
    holds the resolved absolute path (or None when the image was not found).
    """

    source: str
    floor_width: float | None = None  # mm along x; None = no floor size given
    floor_height: float | None = None  # mm along y
    walls: tuple[Wall, ...] = ()
    floor_texture: str | None = None  # resolved path, or None
    start_pose: Pose | None = None  # .wld `position`
    start_positions: tuple[StartPosition, ...] = ()  # .maz start letters, in reading order
    objects: tuple[ObjectPlacement, ...] = ()  # .maz balls and crates, .wld `ball`
    markers: tuple[Marker, ...] = ()  # .maz `F` (finish cell)


@dataclass(frozen=True)
class ObjectType:
    """An object type (.esObj or built-in): model, scale, mass (kg), colliders, flags.

    `scale` applies to the model mesh only; `colliders` and `center_of_mass` are already at the
    object's real size in mm (object frame). `buoyancy` is the displaced volume in litres;
    `fixed` objects never move.
    """

    name: str
    source: str
    model: str | None = None
    scale: float = 1.0
    mass: float = 0.1
    colliders: tuple[Collider, ...] = ()
    color: tuple[int, int, int] = (180, 180, 180)
    buoyancy: float = 0.0
    fixed: bool = False
    center_of_mass: tuple[float, float, float] | None = None


@dataclass(frozen=True)
class RobotPlacement:
    """A robot of a named type placed in the scene, optionally with the program it runs.

    `type_name` is always a key of `Scene.robot_types`."""

    type_name: str
    pose: Pose
    program: str | None = None  # resolved path of the program, or None
    location: Location | None = None


@dataclass(frozen=True)
class Settings:
    vis: bool = False  # draw sensor rays
    trace: bool = False  # draw robot paths
    psd_noise: float = 0.0  # standard deviation (mm) of the Gaussian noise on PSD readings; 0 = exact
    seed: int = 0  # seeds the simulator's random numbers (PSD noise), so runs repeat exactly
    eyesim6_psd: bool = False  # PSDs numbered as EyeSim 6 programs expect: LEFT 1, FRONT 2 (RIGHT 3, BACK 4)
    call_time: float | None = None  # ms of simulation time an ordinary RoBIOS call takes; None = the default


@dataclass(frozen=True)
class Scene:
    """Everything a .sim file describes; the simulator builds its world from this alone.

    `objects` and `markers` are complete: they include the world's own (maze balls, crates and
    finish cells, .wld balls) followed by the .sim file's, so the simulator needs to read only
    these and never `world.objects`/`world.markers`.
    """

    source: str
    world: World
    robot_types: dict[str, RobotType] = field(default_factory=dict)
    object_types: dict[str, ObjectType] = field(default_factory=dict)
    robots: tuple[RobotPlacement, ...] = ()
    objects: tuple[ObjectPlacement, ...] = ()
    markers: tuple[Marker, ...] = ()
    settings: Settings = Settings()
    warnings: tuple[Diagnostic, ...] = ()


__all__ = [
    "Location",
    "Pose",
    "Wall",
    "StartPosition",
    "ObjectPlacement",
    "Marker",
    "World",
    "Collider",
    "ObjectType",
    "RobotPlacement",
    "Settings",
    "Diagnostic",
    "Scene",
    "RobotType",
    "ArmSpec",
    "GripperSpec",
    "JointSpec",
    "CameraSpec",
    "LidarSpec",
    "PsdSpec",
    "ThrusterSpec",
    "BuoyancySpec",
    "DragSpec",
    "SteeringSpec",
    "WheelSpec",
]
