"""Registry of drive archetypes: the `drive` line of a robot type names one of them.

Adding a drive archetype = one new module declaring its DRIVE + one line here (docs/developing.md)."""

from __future__ import annotations

from eyesim.scene.drives import ackermann, arm, differential, omni, submarine
from eyesim.scene.drives.archetype import DriveArchetype

DRIVES: tuple[DriveArchetype, ...] = (
    differential.DRIVE,
    ackermann.DRIVE,
    omni.DRIVE,
    submarine.DRIVE,
    arm.DRIVE,
)

_BY_WORD = {word: drive for drive in DRIVES for word in (drive.name, drive.keyword.lower(), *drive.aliases)}


def drive_named(word: str) -> DriveArchetype | None:
    """The drive a `drive` line's word (any case) or a JSON `drive` value names; None if none."""
    return _BY_WORD.get(word.lower())


def drive_of(robot_type) -> DriveArchetype:
    return _BY_WORD[robot_type.drive]
