"""Built-in robot and object types: our data files load cleanly and have realistic dimensions."""

import pytest

from eyesim.scene import builtins, load_object_type, load_robot_type
from eyesim.scene.description import CameraSpec, PsdSpec, WheelSpec
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.loader import read_definition


@pytest.mark.parametrize("name", builtins.robot_names())
def test_builtin_robots_load_without_any_diagnostic(name):
    diagnostics = Diagnostics()
    robot = read_definition(builtins.robot_path(name), "robot", diagnostics)
    assert robot.name == name and not diagnostics.items


@pytest.mark.parametrize("name", builtins.object_names())
def test_builtin_objects_load_without_any_diagnostic(name):
    diagnostics = Diagnostics()
    obj = read_definition(builtins.object_path(name), "object", diagnostics)
    assert obj.name == name and obj.colliders and not diagnostics.items


def test_every_type_name_the_corpus_uses_without_defining_it():
    for name in ("S4", "LabBot", "labbot", "Labbot", "Can", "can", "Soccer", "Crate", "Golf", "Crate1"):
        assert builtins.robot_path(name) or builtins.object_path(name), name


def test_s4():
    s4 = load_robot_type("S4")
    assert (s4.drive, s4.length, s4.width, s4.height, s4.mass, s4.axis_offset) == ("differential", 180, 150, 90, 0.8, 0)
    assert s4.wheels == WheelSpec(54, 3600, 1100, 90)
    assert s4.psds == (PsdSpec(1, "PSD_FRONT", 90, 0, 40, 0), PsdSpec(2, "PSD_LEFT", 0, 75, 40, 90),
                       PsdSpec(3, "PSD_RIGHT", 0, -75, 40, -90), PsdSpec(4, "PSD_BACK", -90, 0, 40, 180))
    # every sensor on the chassis edge, facing outward
    for psd in s4.psds:
        assert abs(psd.x) == s4.length / 2 or abs(psd.y) == s4.width / 2
    assert s4.camera == CameraSpec(85, 0, 75)


def test_labbot():
    labbot = load_robot_type("labbot")
    assert (labbot.length, labbot.width, labbot.height, labbot.mass) == (200, 180, 155, 1.5)
    assert labbot.wheels == WheelSpec(45, 3600, 540, 140) and labbot.lidar.points == 360
    assert [p.id for p in labbot.psds] == [1, 2, 3, 4]


def test_objects_have_their_real_sizes():
    can, golf = load_object_type("Can"), load_object_type("Golf")
    assert can.colliders[0].size == (33, 122) and can.mass == 0.35
    assert golf.colliders[0].size == (21.35,) and golf.mass == 0.046
    assert load_object_type("Crate1").fixed


def test_builtins_are_loaded_once():
    assert load_robot_type("S4") is load_robot_type("s4")
