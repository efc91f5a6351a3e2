"""Ackermann drive (ACKERMANN_DRIVE, a car): motor 1 drives the rear axle through a differential,
servo 1 steers the front wheels with Ackermann geometry; encoder 1 counts the axle's turns. It
cannot turn on the spot: the V-omega controller drives it along arcs of its rear axle's centre."""

from __future__ import annotations

from eyesim.scene.drives.archetype import DriveArchetype

DRIVE = DriveArchetype(
    "ackermann",
    "ACKERMANN_DRIVE",
    noun="an Ackermann car",
    wheeled=True,
    parts=("wheels", "steering", "axis_offset", "axle_height", "arm"),
    wheel_keyword="wheel drive",
    wheels_outside_hull=True,
    component="eyesim.robot.wheels.ackermann_wheels:AckermannDrive",
)
