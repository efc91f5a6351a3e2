"""The declared drive archetypes: what the rest of the simulator looks up instead of drive names."""

import pytest

from eyesim.robot.drives import DRIVES, ackermann, differential, drive_named, drive_of, omni
from eyesim.robot.drives.archetype import Kinematics, MachineType
from eyesim.scene.json_format import schema
from support.worlds import example_robot


def test_every_drive_word_names_exactly_one_archetype():
    words = [word for drive in DRIVES for word in {drive.name, drive.keyword.lower(), *drive.aliases}]
    assert len(words) == len(set(words))
    for drive in DRIVES:
        assert drive_named(drive.keyword.capitalize()) is drive  # any case, as .robi files write it


def test_the_json_schema_lists_the_declared_drives():
    assert schema("robot")["properties"]["drive"]["enum"] == [drive.name for drive in DRIVES]


@pytest.mark.parametrize("robot,machine,wheeled,swims,mounted", [
    ("Trolley", MachineType.VEHICLE, True, False, False), ("Car", MachineType.VEHICLE, True, False, False),
    ("Mecanum", MachineType.VEHICLE, True, False, False), ("Minnow", MachineType.VEHICLE, False, True, False),
    ("Reacher", MachineType.PLATFORM, False, False, True)])
def test_each_example_robot_gets_its_drives_declared_traits(robot, machine, wheeled, swims, mounted):
    drive = drive_of(example_robot(robot))
    assert (drive.machine_type, drive.wheeled, drive.swims, drive.mounted) == (machine, wheeled, swims, mounted)


def test_the_wheeled_drives_components_offer_kinematics():
    for cls in (differential.DifferentialDrive, ackermann.AckermannDrive, omni.OmniDrive):
        assert issubclass(cls, Kinematics)
