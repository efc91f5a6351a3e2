"""What a drive archetype declares (the `drive` line of a robot type).

Every module in this package declares one `DriveArchetype`; the rest of the simulator asks the
archetype (found by `drives.drive_of(robot_type)`) instead of comparing drive names."""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum
from typing import TYPE_CHECKING, Callable

from eyesim.protocol import constants

if TYPE_CHECKING:
    from eyesim.scene.description import RobotType


class MachineType(IntEnum):
    """What OSMachineType reports (RoBIOS's VEHICLE, PLATFORM; no WALKER drives here)."""

    VEHICLE = constants.VEHICLE
    PLATFORM = constants.PLATFORM


@dataclass(frozen=True)
class DriveArchetype:
    name: str  # RobotType.drive, the JSON `drive` value
    keyword: str  # the .robi `drive` word we write (read in any case)
    noun: str = ""  # what a robot of this drive is, for messages ("an Ackermann car")
    aliases: tuple[str, ...] = ()  # other `drive` words .robi files use (lower case)
    machine_type: MachineType = MachineType.VEHICLE
    mounted: bool = False  # the base is bolted to the floor (no free joint)
    swims: bool = False  # a scene with such a robot is under water (physics/water.py)
    wheeled: bool = False  # needs a `wheel` line (a missing one gets the S4's wheels)
    wheel_keyword: str = "wheel"  # how the .robi writer introduces its driven wheels
    wheels_outside_hull: bool = False  # its wheels widen the floor-plan footprint (scene/placement.py)
    # The viewer draws two wheels from the scene message's wheel_diameter/track; other drives'
    # wheels are parts the viewer draws from their own geoms (web/scene_message.py).
    viewer_wheels: bool = False
    # The drive's own component (its wheels and motors) as "module:Class", built when the robot
    # type has wheels; "" when other components move it. A name, not an import: declarations sit
    # below the physics (docs/architecture.md, "Layers"), robot/wheels/ resolves it.
    component: str = ""
    # The robot fields of drive-dependent parts (robot schema keys) this drive can use; the robot
    # editor offers only these (an arm rides on wheels too: the Picker).
    parts: tuple[str, ...] = ()
    # A warning (message, code) about a robot type of this drive that cannot move, else None.
    # (RobotType is assembled with make_dataclass, which mypy cannot take for a type)
    check: Callable[[RobotType], tuple[str, str] | None] = lambda robot: None  # type: ignore[valid-type]
