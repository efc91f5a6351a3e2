"""The declared drive archetypes: what the rest of the simulator looks up instead of drive names."""

import subprocess
import sys
from pathlib import Path

import pytest

from eyesim.robot.wheels import ackermann_wheels, differential_wheels, omni_wheels
from eyesim.robot.wheels.kinematics import Kinematics
from eyesim.scene.drives import DRIVES, drive_named, drive_of
from eyesim.scene.drives.archetype import MachineType
from eyesim.scene.json_format import schema
from support.worlds import example_robot


def test_every_drive_word_names_exactly_one_archetype():
    words = [word for drive in DRIVES for word in {drive.name, drive.keyword.lower(), *drive.aliases}]
    assert len(words) == len(set(words))
    for drive in DRIVES:
        assert drive_named(drive.keyword.capitalize()) is drive  # any case, as .robi files write it


def test_the_json_schema_lists_the_declared_drives():
    assert schema("robot")["properties"]["drive"]["enum"] == [drive.name for drive in DRIVES]


@pytest.mark.parametrize(
    "robot,machine,wheeled,swims,mounted",
    [
        ("Trolley", MachineType.VEHICLE, True, False, False),
        ("Car", MachineType.VEHICLE, True, False, False),
        ("Mecanum", MachineType.VEHICLE, True, False, False),
        ("Minnow", MachineType.VEHICLE, False, True, False),
        ("Reacher", MachineType.PLATFORM, False, False, True),
    ],
)
def test_each_example_robot_gets_its_drives_declared_traits(robot, machine, wheeled, swims, mounted):
    drive = drive_of(example_robot(robot))
    assert (drive.machine_type, drive.wheeled, drive.swims, drive.mounted) == (machine, wheeled, swims, mounted)


def test_the_declarations_and_the_scene_package_need_no_physics():
    """Reading, checking and converting scene files never loads MuJoCo (only the drives' components do)."""
    code = (
        "import sys, eyesim.scene, eyesim.scene.cli, eyesim.scene.drives; "
        "assert 'mujoco' not in sys.modules, sorted(m for m in sys.modules if m.startswith('eyesim'))"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=Path(__file__).parent)
    assert result.returncode == 0, result.stderr


def test_the_wheeled_drives_components_offer_kinematics():
    for cls in (differential_wheels.DifferentialDrive, ackermann_wheels.AckermannDrive, omni_wheels.OmniDrive):
        assert issubclass(cls, Kinematics)


def test_each_declared_component_name_resolves_to_a_kinematics_component():
    """A declaration names its wheel component by module path (declarations sit below the physics);
    the name must resolve, and only drives that need wheels name one."""
    import importlib

    named = {}
    for drive in DRIVES:
        if not drive.component:
            continue
        module, name = drive.component.split(":")
        named[drive.name] = getattr(importlib.import_module(module), name)
        assert drive.wheeled and issubclass(named[drive.name], Kinematics)
    assert named == {
        "differential": differential_wheels.DifferentialDrive,
        "ackermann": ackermann_wheels.AckermannDrive,
        "omni": omni_wheels.OmniDrive,
    }
