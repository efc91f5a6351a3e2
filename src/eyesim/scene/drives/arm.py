"""Manipulator on a fixed base (ARM): bolted to the floor, a PLATFORM to OSMachineType; its `joint`
and `gripper` lines move it (the arm and gripper components)."""

from eyesim.scene.drives.archetype import DriveArchetype, MachineType


def check(robot) -> tuple[str, str] | None:
    if robot.arm is None or not robot.arm.joints:
        return "an arm robot without 'joint' lines cannot move", "no-joints"
    return None


DRIVE = DriveArchetype(
    "arm",
    "ARM",
    noun="a manipulator arm on a fixed base",
    aliases=("arm_drive",),
    machine_type=MachineType.PLATFORM,
    mounted=True,
    parts=("arm",),
    check=check,
)
