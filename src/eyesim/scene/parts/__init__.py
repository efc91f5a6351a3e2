"""Registry of robot part kinds, and what is assembled from their declarations: the RobotType
dataclass, the `.robi` keyword table and the published robot JSON Schema.

Adding a part kind = one folder, parts/<kind>/ (its declaration.py declares its PART, see
parts/part.py; its component.py what it does in the simulation; its calls.py its RoBIOS
handlers), + one line here. Kinds not yet in a folder of their own are modules of this package."""

from __future__ import annotations

import dataclasses

from eyesim.parts.bumper import declaration as bumper
from eyesim.parts.camera import declaration as camera
from eyesim.parts.lidar import declaration as lidar
from eyesim.parts.psd import declaration as psd
from eyesim.scene.parts import arm, body, drive, thrusters, water, wheels
from eyesim.parts.part import Part

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

RobotType = dataclasses.make_dataclass(
    "RobotType",
    [("name", str), ("source", str)]
    + [(name, kind, dataclasses.field(default=default)) for part in PARTS for name, kind, default in part.fields],
    frozen=True,
)
RobotType.__module__ = "eyesim.scene.description"  # where it has always been imported from
RobotType.__doc__ = """A robot type: what a .robi file (or a built-in definition) says about a robot.

`name` and `source` (the file it came from), then the fields each part kind declares
(scene/parts/): `drive` is one of the drive archetypes (scene/drives); a wheeled robot may also
carry an `arm`: drive commands then move the base and servo commands the arm."""

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
