"""Summary lines of `eyesim check`."""

from eyesim.scene import load_object_type, load_robot_type, load_scene
from eyesim.scene.summary import object_lines, robot_lines, scene_lines
from scene_testing import CORPUS


def test_scene_lines():
    lines = scene_lines(load_scene(CORPUS / "azri41__Eyesim--Prey-and-Predator/01-w5_simulation.sim"))
    assert lines[0] == "world 00-field.maz: floor 10000 x 9000 mm, 4 walls within x 0..10000, y 0..9000"
    assert "maze starts U (3500, 500, 90 deg), S (5500, 500, 90 deg)" in lines
    assert "robot S4 at (5500, 500, 100 deg)" in lines[2]
    assert lines[-1] == "settings VIS TRACE"


def test_robot_and_object_lines():
    assert robot_lines(load_robot_type("LabBot"))[1].endswith("camera, lidar 360 points")
    assert object_lines(load_object_type("Crate1")) == ["object type Crate1: 1 kg, 1 collider, no model, fixed"]
