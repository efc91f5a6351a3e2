"""Built-in robot and object types: our data files load cleanly and have realistic dimensions."""

from pathlib import Path

import pytest

from eyesim.scene import builtins, load_object_type, load_robot_type, load_scene
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
    assert s4.psds == (
        PsdSpec(1, "PSD_FRONT", 90, 0, 40, 0),
        PsdSpec(2, "PSD_LEFT", 0, 75, 40, 90),
        PsdSpec(3, "PSD_RIGHT", 0, -75, 40, -90),
        PsdSpec(4, "PSD_BACK", -90, 0, 40, 180),
    )
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


def test_mako_is_numbered_as_the_eyesim_submarine_examples_expect():
    mako = load_robot_type("Mako")
    assert mako.drive == "submarine"
    thrusters = {t.name: (t.motor, (t.dx, t.dy, t.dz)) for t in mako.thrusters}
    assert thrusters == {
        "LEFT": (1, (1, 0, 0)),
        "FRONT": (2, (0, 0, 1)),
        "RIGHT": (3, (1, 0, 0)),
        "BACK": (4, (0, 0, 1)),
    }
    by_id = {p.id: p for p in mako.psds}
    assert [by_id[i].name for i in range(1, 7)] == [
        "PSD_FRONT",
        "PSD_FRONT_LEFT",
        "PSD_FRONT_RIGHT",
        "PSD_BACK_LEFT",
        "PSD_BACK_RIGHT",
        "PSD_DOWN",
    ]
    assert by_id[6].pitch == -90 and by_id[1].heading == 0 and by_id[2].heading == 90
    assert mako.camera is not None and mako.camera.x > 0
    # it floats: more water displaced than it weighs
    assert mako.buoyancy.volume > mako.mass


@pytest.mark.parametrize("name", builtins.scene_names())
def test_bundled_scenes_load_without_warnings(name):
    assert not load_scene(builtins.scene_path(name)).warnings


def test_a_bundled_scene_is_named_on_the_command_line_by_its_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert builtins.scene_argument("mako_pool") == builtins.SCENES_DIR / "mako_pool.sim"
    assert builtins.scene_argument("MAKO_POOL.sim") == builtins.SCENES_DIR / "mako_pool.sim"
    (tmp_path / "mako_pool.sim").write_text("")
    assert builtins.scene_argument("mako_pool.sim") == Path("mako_pool.sim")  # a file of that name wins
    assert builtins.scene_argument("elsewhere/mako_pool") == Path("elsewhere/mako_pool")  # a path is a path


def test_every_stock_robot_name_stands_for_a_built_in_robot():
    for stock, builtin in builtins.STOCK_ROBOTS.items():
        assert builtins.robot_path(builtin) is not None, stock
        assert builtins.robot_path(stock) is None, f"{stock} is a built-in itself"


@pytest.mark.parametrize(
    "reference, builtin, drive",
    [
        ("%sim%/robots/ModelCar/ModelCar.robi", "Car", "ackermann"),  # EyeSim 6 drivemodes/Ackermann.sim
        ("%sim%/robots/Omni/Omni2.robi", "Omni", "omni"),  # drivemodes/Omni.sim
        ("%sim%/robots/Eve/Eve.robi", "S4", "differential"),  # maze/MazeSearch.sim
        ("/robots/Ackermann/Ackermann.robi", "Car", "ackermann"),  # EyeSim VR's test assets
        ("robots/Omni/Omni3.robi", "Omni", "omni"),  # a file of EyeSim's Omni folder: named by its folder
        ("..\\robots\\ModelCar\\ModelCar2.robi", "Car", "ackermann"),
    ],
)
def test_a_missing_stock_robot_file_gets_the_built_in_of_its_drive_and_says_which(tmp_path, reference, builtin, drive):
    (tmp_path / "w.wld").write_text("floor 3000 3000\n")
    (tmp_path / "a.sim").write_text(f"world w.wld\nrobi {reference} drive.dll 600 500 0\n")
    scene = load_scene(tmp_path / "a.sim")
    (placement,) = scene.robots
    robot = scene.robot_types[placement.type_name]
    stand_in = load_robot_type(builtin)
    assert placement.type_name == Path(reference.replace("\\", "/")).stem
    assert robot.drive == drive
    assert (robot.psds, robot.camera, robot.wheels) == (stand_in.psds, stand_in.camera, stand_in.wheels)
    (warning,) = [w for w in scene.warnings if reference in w.message]
    assert warning.code == "missing-file" and f"using the built-in {builtin} " in warning.message


def test_a_missing_robot_file_of_no_stock_name_falls_back_to_the_s4_and_says_so(tmp_path):
    (tmp_path / "a.sim").write_text("robi bots/Rover.robi\nRover 600 500 0\n")
    scene = load_scene(tmp_path / "a.sim")
    assert scene.robot_types["Rover"].drive == "differential"
    (warning,) = [w for w in scene.warnings if "Rover.robi" in w.message]
    assert "using the built-in S4 (a two-wheeled differential drive robot) as robot type 'Rover'" in warning.message


def test_omni_is_numbered_as_eyesims_omni_robot_files():
    omni = load_robot_type("Omni")
    assert omni.drive == "omni" and omni.wheels == WheelSpec(100, 360, 7300, 220)
    assert [(p.id, p.name) for p in omni.psds] == [
        (1, "PSD_FRONT"),
        (2, "PSD_LEFT"),
        (3, "PSD_RIGHT"),
        (4, "PSD_BACK"),
        (5, "PSD_FRONT2"),
        (6, "PSD_LEFTDIAG"),
        (7, "PSD_RIGHTDIAG"),
    ]
    assert omni.camera is not None and omni.camera.x > 0
    assert omni.drive_motors[::2] == ("MOTOR_FL", "MOTOR_FR", "MOTOR_BL", "MOTOR_BR")
