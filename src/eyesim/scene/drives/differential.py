"""Differential drive (DIFFERENTIAL_DRIVE): two driven wheels with encoders (motors/encoders 1 = left,
2 = right) and casters; turns on the spot."""

from __future__ import annotations

from eyesim.scene.drives.archetype import DriveArchetype

DRIVE = DriveArchetype(
    "differential",
    "DIFFERENTIAL_DRIVE",
    noun="a two-wheeled differential drive robot",
    wheeled=True,
    parts=("wheels", "axis_offset", "axle_height", "arm"),
    wheels_outside_hull=True,
    viewer_wheels=True,
    component="eyesim.robot.wheels.differential_wheels:DifferentialDrive",
)
