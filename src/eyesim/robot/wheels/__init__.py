"""The drives' physics: the wheel components that the drive declarations (eyesim/scene/drives/) name."""

from __future__ import annotations

from eyesim.robot.component import named
from eyesim.scene.drives import drive_of


def create(context) -> list:
    """The component factory for the robot's drive (robot/components registry): the component its
    declaration names, when the robot type has wheels."""
    drive = drive_of(context.robot_type)
    if not drive.component or context.robot_type.wheels is None:
        return []
    return [named(drive.component)(context)]
