"""The `drive` line: which drive archetype (scene/drives) moves the robot, and its EyeSim 6
motor and encoder names."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.scene.diagnostics import quoted
from eyesim.scene.drives import DRIVES, drive_named, drive_of
from eyesim.scene.lexer import Line
from eyesim.parts.part import Part, PartReader, choice, in_schema
from eyesim.scene.parts.wheels import DEFAULT_WHEELS

DRIVE_CHOICES = ", ".join(drive.keyword for drive in DRIVES[:-1]) + f" or {DRIVES[-1].keyword}"


@dataclass(frozen=True, kw_only=True)
class DriveFields:
    """Which drive archetype moves a robot type, and its EyeSim 6 motor and encoder names."""

    drive: str = field(
        default="differential",
        metadata=in_schema(
            choice("Drive", [drive.name for drive in DRIVES], "the drive archetype that moves the robot")
        ),
    )
    drive_motors: tuple[str, ...] = field(
        default=(),
        metadata=in_schema(
            {
                "title": "EyeSim 6 motor names",
                "type": "array",
                "items": {"type": "string"},
                "description": "EyeSim 6 motor and encoder names",
            }
        ),
    )


def read_drive(reader: PartReader, line: Line) -> None:
    if not line.args:
        reader.error(line, f"drive: expected a drive type ({DRIVE_CHOICES}), found nothing")
        return
    drive = drive_named(line.args[0].text)
    if drive is None:
        reader.error(line, f"drive: expected {DRIVE_CHOICES}, found {quoted(line.args[0].text)}", 1)
        return
    reader.fields["drive"] = drive.name
    reader.fields["drive_motors"] = tuple(t.text for t in line.args[1:])
    reader.remember("drive", line)


def check(robot, diagnostics, at) -> dict:
    drive, changes = drive_of(robot), {}
    if drive.wheeled and robot.wheels is None:
        diagnostics.warning(
            at("drive"),
            f"a {robot.drive} robot needs a 'wheel' line; using the S4's wheels "
            "(54 mm, 3600 deg/s, 1100 ticks, track 90 mm)",
            "missing-wheels",
        )
        changes["wheels"] = DEFAULT_WHEELS
    immobile = drive.check(robot)
    if immobile is not None:
        diagnostics.warning(at("drive"), *immobile)
    return changes


def write(robot) -> list[str]:
    return [" ".join(["drive", drive_of(robot).keyword, *robot.drive_motors])]


PART = Part(
    "drive",
    fields=DriveFields,
    keywords={"drive": read_drive},
    write=write,
    json_locations=lambda robot, positions: {"drive": positions.key(["drive"])},
    check=check,
)
