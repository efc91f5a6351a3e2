"""Immutable scene description: what the scene files say, as frozen dataclasses.

Units are the files' own (millimetres, degrees, kilograms, 0-255 colour channels) so that text
and JSON convert into each other without loss; `physics/` converts to SI when it builds a model.
World frame: x east, y north, z up, origin at the floor's lower-left corner, headings in degrees
counter-clockwise from +x. Robot frame: x forward, y left, z up, origin at the robot's centre on
the floor.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Location:
    """Where something came from, for messages: file, 1-based line and column (0 = unknown)."""

    file: str
    line: int = 0
    column: int = 0

    def __str__(self) -> str:
        if self.line and self.column:
            return f"{self.file}:{self.line}:{self.column}"
        if self.line:
            return f"{self.file}:{self.line}"
        return self.file


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
    """An object of a named type placed in the world."""

    type_name: str
    pose: Pose
    location: Location | None = None


@dataclass(frozen=True)
class World:
    """The environment: floor, walls and what a .wld or .maz file places in it."""

    source: str
    floor_width: float | None = None  # mm along x; None = no floor size given
    floor_height: float | None = None  # mm along y
    walls: tuple[Wall, ...] = ()
    floor_texture: str | None = None  # resolved path, or None
    start_pose: Pose | None = None  # .wld `position`
    start_positions: tuple[StartPosition, ...] = ()  # .maz start letters, in reading order
    objects: tuple[ObjectPlacement, ...] = ()  # .maz balls and crates


@dataclass(frozen=True)
class WheelSpec:
    """Wheels of a wheeled drive: diameter mm, max speed deg/s, encoder ticks per revolution,
    track = full distance between the left and right wheel contact points in mm."""

    diameter: float
    max_speed: float
    ticks_per_rev: int
    track: float


@dataclass(frozen=True)
class PsdSpec:
    """A PSD distance sensor: RoBIOS id (PSD_FRONT=1 ...), name, position in the robot frame (mm)
    and beam direction (heading deg, left positive; pitch deg, up positive)."""

    id: int
    name: str
    x: float
    y: float
    z: float
    heading: float
    pitch: float = 0.0


@dataclass(frozen=True)
class CameraSpec:
    """A camera at a robot-frame position (mm) with default pan/tilt (deg) and field of view."""

    x: float
    y: float
    z: float
    pan: float = 0.0
    tilt: float = 0.0
    fov: float = 60.0
    pan_servo: int | None = None
    tilt_servo: int | None = None


@dataclass(frozen=True)
class LidarSpec:
    points: int = 360
    tilt: float = 0.0


@dataclass(frozen=True)
class Collider:
    """A collision shape in the robot/object frame (mm): kind 'box' (size = sx, sy, sz),
    'sphere' (size = (r,)), 'capsule' (size = (r, h)) or 'cylinder' (size = (r, h)), with its
    centre and, for capsules/cylinders, the axis letter."""

    kind: str
    size: tuple[float, ...]
    center: tuple[float, float, float] = (0.0, 0.0, 0.0)
    axis: str = "z"


@dataclass(frozen=True)
class RobotType:
    """A robot type: what a .robi file (or a built-in definition) says about a robot.

    `drive` is one of 'differential', 'ackermann', 'omni', 'submarine', 'arm' (and combinations
    added by later issues). Dimensions: `length`, `width`, `height` of the chassis in mm.
    """

    name: str
    source: str
    drive: str = "differential"
    mass: float = 0.6  # kg
    length: float = 180.0
    width: float = 150.0
    height: float = 80.0
    color: tuple[int, int, int] = (40, 90, 200)
    max_speed: float = 600.0  # mm/s
    max_turn: float = 300.0  # deg/s
    axis_offset: float = 0.0  # mm the drive axle sits ahead (+) of the robot centre
    wheels: WheelSpec | None = None
    psds: tuple[PsdSpec, ...] = ()
    camera: CameraSpec | None = None
    lidar: LidarSpec | None = None
    model: str | None = None
    colliders: tuple[Collider, ...] = ()
    extras: tuple[tuple[str, object], ...] = ()  # keywords later drive types add


@dataclass(frozen=True)
class ObjectType:
    """An object type (.esObj or built-in): model, scale, mass (kg), colliders, flags."""

    name: str
    source: str
    model: str | None = None
    scale: float = 1.0
    mass: float = 0.1
    colliders: tuple[Collider, ...] = ()
    color: tuple[int, int, int] = (180, 180, 180)
    buoyancy: float = 0.0
    fixed: bool = False


@dataclass(frozen=True)
class RobotPlacement:
    """A robot of a named type placed in the scene, optionally with the program it runs."""

    type_name: str
    pose: Pose
    program: str | None = None  # resolved path of the program, or None
    location: Location | None = None


@dataclass(frozen=True)
class Marker:
    x: float
    y: float
    color: tuple[int, int, int, int] = (255, 0, 0, 255)


@dataclass(frozen=True)
class Settings:
    vis: bool = False  # draw sensor rays
    trace: bool = False  # draw robot paths


@dataclass(frozen=True)
class Diagnostic:
    """A warning or error found while loading: kind ('error' | 'warning'), where, and what."""

    kind: str
    location: Location
    message: str

    def __str__(self) -> str:
        return f"{self.location}: {self.kind}: {self.message}"


@dataclass(frozen=True)
class Scene:
    """Everything a .sim file describes; the simulator builds its world from this alone."""

    source: str
    world: World
    robot_types: dict[str, RobotType] = field(default_factory=dict)
    object_types: dict[str, ObjectType] = field(default_factory=dict)
    robots: tuple[RobotPlacement, ...] = ()
    objects: tuple[ObjectPlacement, ...] = ()
    markers: tuple[Marker, ...] = ()
    settings: Settings = Settings()
    warnings: tuple[Diagnostic, ...] = ()
