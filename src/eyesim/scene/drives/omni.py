"""Omni drive (OMNI_DRIVE): four mecanum wheels (motors/encoders 1 front left, 2 front right, 3 back left,
4 back right), so the robot can drive in any direction and turn at the same time.

A mecanum wheel's rollers sit at 45 degrees: the wheel only pushes along its bottom roller's axis
and rolls freely across it. That is modelled exactly by a plain wheel turned by 45 degrees that
rolls along the roller's axis and slides freely along its own axle (a capsule touching the floor,
whose contact friction is high along the rolling direction and nearly zero along the axle). As it
rolls cos 45 as far per turn, it is geared to its motor by 1/cos 45 (a tendon), so the motor and
its encoder turn exactly like the real wheel."""

from __future__ import annotations

from eyesim.scene.drives.archetype import DriveArchetype

DRIVE = DriveArchetype("omni", "OMNI_DRIVE", wheeled=True,
                       component="eyesim.robot.drives.omni_wheels:OmniDrive")
