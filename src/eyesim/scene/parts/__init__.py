"""Registry of robot part kinds, and what is assembled from their declarations: the RobotType
dataclass, the `.robi` keyword table and the published robot JSON Schema.

Adding a part kind = one folder, parts/<kind>/ (its declaration.py declares its PART, see
parts/part.py; its component.py what it does in the simulation; its calls.py its RoBIOS
handlers), + its PART in PARTS and its fields among RobotType's bases here.

The robot's base stays in this package: the body (chassis), the drive line and the wheels
(body.py, drive.py, wheels.py). Every robot type has them, they name no component of their own
(the robot builder makes the chassis, robot/wheels the drive's wheels and the VW controller drives
them, for any drive archetype of scene/drives), and the other parts read them (the arm sits on the
chassis, the buoyancy acts on its hull)."""

from __future__ import annotations

from dataclasses import dataclass

from eyesim.parts.arm import declaration as arm
from eyesim.parts.bumper import declaration as bumper
from eyesim.parts.camera import declaration as camera
from eyesim.parts.lidar import declaration as lidar
from eyesim.parts.psd import declaration as psd
from eyesim.parts.thrusters import declaration as thrusters
from eyesim.parts.water import declaration as water
from eyesim.scene.parts import body, drive, wheels
from eyesim.parts.part import Part, text

# In this order the reader finishes them (the arm sits on the chassis: after the body), their
# checks run, the writer writes their lines and RobotType lists their fields.
PARTS: tuple[Part, ...] = (
    drive.PART,
    body.PART,
    wheels.PART,
    psd.PART,
    bumper.PART,
    camera.PART,
    lidar.PART,
    thrusters.PART,
    water.PART,
    arm.PART,
)


def _keywords() -> dict:
    table: dict = {}
    for part in PARTS:
        for word, read in part.keywords.items():
            if word in table:
                raise ValueError(f"the .robi keyword {word!r} is declared by two parts")
            table[word] = read
    return table


KEYWORDS = _keywords()  # .robi keyword (lower case) -> function(reader, line)


@dataclass(frozen=True)
class Named:
    """What every robot type has: its name and the file it came from (not written in files)."""

    name: str
    source: str


# The bases are the parts' fields, last part first: a dataclass lists the fields of its last base
# first, so RobotType's fields come in the order of PARTS, after `name` and `source`.
@dataclass(frozen=True)
class RobotType(
    arm.ArmFields,
    water.WaterFields,
    thrusters.ThrustersFields,
    lidar.LidarFields,
    camera.CameraFields,
    bumper.BumperFields,
    psd.PsdFields,
    wheels.WheelsFields,
    body.BodyFields,
    drive.DriveFields,
    Named,
):
    """A robot type: what a .robi file (or a built-in definition) says about a robot.

    `name` and `source` (the file it came from), then the fields each part kind declares
    (parts/<kind>/declaration.py; the base's in scene/parts/): `drive` is one of the drive archetypes
    (scene/drives); a wheeled robot may also carry an `arm`: drive commands then move the base and
    servo commands the arm."""


def check_bases(robot_type: type, parts: tuple[Part, ...]) -> None:
    """Refuses a robot type class whose bases are not the parts' fields, last part first."""
    expected = tuple(part.fields for part in reversed(parts)) + (Named,)
    if robot_type.__bases__ != expected:
        names = ", ".join(base.__name__ for base in expected)
        raise TypeError(f"RobotType must derive from the parts' fields, last part first: {names}")


check_bases(RobotType, PARTS)
RobotType.__module__ = "eyesim.scene.description"  # where it has always been imported from

ROBOT_SCHEMA_HEAD = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "$id": "urn:eyesim:schema:robot:1",
    "title": "EyeSim robot type",
    "description": "A .robi robot definition as JSON. Positions are in the robot frame (x forward, y left, z up, mm), "
    "angles in degrees.",
}


def robot_schema() -> dict:
    """The published JSON Schema of a robot file (robot.schema.json), from the parts' fragments."""
    properties = {
        "format": {"title": "Format", "const": "eyesim.robot", "description": "which EyeSim file format this is"},
        "version": {"title": "Version", "const": 1, "description": "format version"},
        "name": text("Name"),
    }
    defs: dict = {}
    for part in PARTS:
        properties.update(part.properties)
        defs.update(part.defs)
    return {
        **ROBOT_SCHEMA_HEAD,
        "type": "object",
        "required": ["format", "version", "name"],
        "additionalProperties": False,
        "properties": properties,
        "$defs": defs,
    }
