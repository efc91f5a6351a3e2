"""Omni drive (OMNI_DRIVE): four mecanum wheels (motors/encoders 1 front left, 2 front right, 3 back left,
4 back right), so the robot can drive in any direction and turn at the same time.

How the mecanum wheels are modelled: eyesim/robot/wheels/omni_wheels.py."""

from __future__ import annotations

from eyesim.scene.drives.archetype import DriveArchetype

DRIVE = DriveArchetype(
    "omni",
    "OMNI_DRIVE",
    noun="a mecanum omni-drive robot",
    wheeled=True,
    parts=("wheels", "axle_height", "arm"),
    component="eyesim.robot.wheels.omni_wheels:OmniDrive",
)
