"""Differential drive (DIFFERENTIAL_DRIVE): two driven wheels with encoders (motors/encoders 1 = left,
2 = right) and casters; turns on the spot."""

from __future__ import annotations

from eyesim.robot.drives.archetype import DriveArchetype


def components(context) -> list:
    # imported here: the drive's physics needs MuJoCo, its declaration (what scene files name) does not
    from eyesim.robot.drives.differential_wheels import DifferentialDrive
    return [DifferentialDrive(context)] if context.robot_type.wheels is not None else []


DRIVE = DriveArchetype("differential", "DIFFERENTIAL_DRIVE", wheeled=True,
                       wheels_outside_hull=True, viewer_wheels=True, components=components)
