"""Loading whole scenes: every real corpus file, references, fallbacks, start poses, errors."""

import json
import re
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from eyesim.scene import DEFAULT_SCENE, Pose, SceneError, load_object_type, load_robot_type, load_scene, load_world
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.loader import read_definition
from scene_testing import CORPUS, corpus_texts, manifest

EXPECTED_WARNINGS = json.loads((Path(__file__).parent / "corpus_warnings.json").read_text(encoding="utf-8"))


def warning_keys(warnings):
    keys = []
    for w in warnings:
        file = Path(w.location.file)
        file = file.relative_to(CORPUS).as_posix() if file.is_relative_to(CORPUS) else file.as_posix()
        target = re.search(r"not found: ('[^']*'|\"[^\"]*\")", w.message)
        keys.append(f"{w.code} {file}:{w.location.line}" + (f" {target.group(1)}" if target else ""))
    return sorted(keys)


def test_the_corpus_is_there():
    assert len(manifest()) == 275


@pytest.mark.parametrize("relative, kind", manifest())
def test_every_corpus_file_loads(relative, kind):
    path = CORPUS / relative
    if kind in ("sim", "wld", "maz"):
        scene = load_scene(path)
        warnings = scene.warnings
        for robot in scene.robots:
            assert robot.type_name in scene.robot_types
        for obj in scene.objects:
            assert obj.type_name in scene.object_types
    else:
        diagnostics = Diagnostics()
        assert read_definition(path, "robot" if kind == "robi" else "object", diagnostics) is not None
        warnings = diagnostics.items
    # the only warnings are the listed ones: files genuinely absent and the known slips of the corpus
    assert warning_keys(warnings) == sorted(EXPECTED_WARNINGS.get(relative, []))


def test_maze_start_letter_gives_the_start_pose():
    scene = load_scene(CORPUS / "LDY681__AUTO4508-labs/lab7/Maze.sim")
    assert [(r.type_name, r.pose) for r in scene.robots] == [("S4", Pose(360, 360, 90))]
    assert scene.robot_types["S4"].wheels.diameter == 54


def test_the_number_after_a_start_letter_is_the_heading():
    scene = load_scene(CORPUS / "azri41__Eyesim--Prey-and-Predator/01-w5_simulation.sim")
    assert [r.pose for r in scene.robots] == [Pose(5500, 500, 100), Pose(3500, 500, 65)]


def test_eyesim6_robots_start_at_the_maze_start_or_world_position():
    maze = load_scene(CORPUS / "ASAX21__VRRoboticProject/Test Assets/examples/maze/MazeSearch.sim")
    assert maze.robots[0].pose == Pose(180, 180, 90)
    world = load_scene(CORPUS / "ASAX21__VRRoboticProject/Test Assets/examples/omni/ODW-world.sim")
    assert world.robots[0].pose == Pose(15800, 5800, 0) and world.robots[0].type_name == "ODW"
    assert world.robot_types["ODW"].drive == "omni"


def test_custom_types_windows_paths_and_case():
    scene = load_scene(CORPUS / "NoahWMueller__Eyesim/Sims/Carolo_1_Centroids.sim")
    assert {o.type_name for o in scene.objects} == {"StopSign", "10SpeedLimitSign", "SpeedLimitSign"}
    assert Path(scene.object_types["StopSign"].model).name == "STOP.obj"  # written 'Stop.obj'
    assert Path(scene.world.floor_texture).name == "Carolo_Centroids.png"  # ..\..\images-videos\...


def test_builtin_names_in_any_case_and_maze_objects():
    scene = load_scene(CORPUS / "ASAX21__VRRoboticProject/Test Assets/simple.sim")
    assert [r.type_name for r in scene.robots] == ["LabBot"]  # written 'labbot'
    assert sorted(o.type_name for o in scene.objects) == ["Crate", "Crate", "Soccer", "Soccer"]
    assert set(scene.object_types) == {"Crate", "Soccer"}


def make(root, name, text):
    path = root / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def test_programs_resolve_to_absolute_paths(tmp_path):
    program = make(tmp_path, "progs/drive.py", "print(1)")
    scene = make(tmp_path, "a.sim", "world w.wld\nS4 100 100 0 progs/drive.py\nS4 300 300 0 missing.x\n")
    make(tmp_path, "w.wld", "floor 1000 1000\n")
    loaded = load_scene(scene)
    assert loaded.robots[0].program == str(program)
    assert loaded.robots[1].program == "missing.x"
    (warning,) = loaded.warnings
    assert (warning.code, warning.location.line, warning.location.column) == ("missing-file", 3, 1)


def test_missing_references_fall_back_with_warnings(tmp_path):
    scene = make(
        tmp_path,
        "a.sim",
        "world nowhere.wld\nrobot bots/Rover.robi\nobject props/Cone.esObj\nRover 1 2 3\nCone 400 5 6\n",
    )  # apart: an overlap would warn too
    loaded = load_scene(scene)
    assert loaded.world.walls == () and loaded.robot_types["Rover"].wheels.diameter == 54
    assert loaded.object_types["Cone"].colliders[0].kind == "box"
    assert [w.location.line for w in loaded.warnings] == [1, 2, 3]
    assert all(w.code == "missing-file" for w in loaded.warnings)


def test_missing_texture_and_model(tmp_path):
    world = make(tmp_path, "w.wld", "floor 1000 1000\nfloor_texture gone.png\n")
    make(tmp_path, "r.robi", "dialect eyesim\nname R\nwheel 54 3600 1100 90\nmodel gone.obj\n")
    loaded = load_world(world)
    assert loaded.floor_texture is None
    robot_diagnostics = Diagnostics()
    robot = read_definition(tmp_path / "r.robi", "robot", robot_diagnostics)
    assert robot.model is None
    (warning,) = robot_diagnostics.items
    assert (warning.location.line, warning.location.column) == (4, 7)


def test_found_texture_is_absolute(tmp_path):
    image = make(tmp_path, "img/Floor.PNG", "x")
    world = make(tmp_path, "w.wld", "floor 1000 1000\nfloor_texture img\\floor.png\n")
    assert load_world(world).floor_texture == str(image)


def test_errors_in_referenced_files_are_reported_with_their_location(tmp_path):
    make(tmp_path, "bad.robi", "dialect eyesim\nname Bad\nwheel 54 x 1100 90\n")
    scene = make(tmp_path, "a.sim", "robot bad.robi\nBad 1 2 3\nS5 1 1 1\n")
    with pytest.raises(SceneError) as caught:
        load_scene(scene)
    text = str(caught.value)
    assert f"{tmp_path / 'bad.robi'}:3:10: error: wheel: expected maximum speed in deg/s (a number), found 'x'" in text
    assert f"{tmp_path / 'a.sim'}:3:1: error: unknown robot or object type 'S5' (did you mean 'S4'?)" in text
    assert all(d.kind in ("error", "warning") for d in caught.value.diagnostics)


def test_a_type_defined_twice_is_an_error(tmp_path):
    make(tmp_path, "a.robi", "dialect eyesim\nname Twin\nwheel 54 3600 1100 90\n")
    make(tmp_path, "b.robi", "dialect eyesim\nname Twin\nwheel 54 3600 1100 90\n")
    scene = make(tmp_path, "s.sim", "world w.maz\nrobot a.robi\nrobot b.robi\nrobot a.robi\n")
    make(tmp_path, "w.maz", " _\n|_|\n")
    with pytest.raises(SceneError, match="defined twice"):
        load_scene(scene)


def test_objects_take_no_program(tmp_path):
    scene = make(tmp_path, "s.sim", "Can 1 2 3 prog.x\n")
    with pytest.raises(SceneError, match="'Can' is an object"):
        load_scene(scene)


def test_bare_worlds_mazes_and_json(tmp_path):
    maze = load_scene(CORPUS / "ASAX21__VRRoboticProject/Test Assets/maze1.maz")
    assert maze.robots == () and len(maze.objects) == 4 and set(maze.object_types) == {"Crate", "Soccer"}
    world = make(
        tmp_path,
        "w.json",
        json.dumps(
            {
                "format": "eyesim.world",
                "version": 1,
                "floor_width": 100,
                "floor_height": 100,
                "walls": [{"x1": 0, "y1": 0, "x2": 1, "y2": 0}],
            }
        ),
    )
    assert len(load_scene(world).world.walls) == 1


def test_unknown_file_types_and_unreadable_files(tmp_path):
    with pytest.raises(SceneError, match="unknown file type"):
        load_scene(make(tmp_path, "a.txt", "x"))
    with pytest.raises(SceneError, match="cannot read"):
        load_scene(tmp_path / "absent.sim")
    binary = tmp_path / "b.wld"
    binary.write_bytes(b"\x00\x01")
    with pytest.raises(SceneError, match="NUL"):
        load_scene(binary)
    with pytest.raises(SceneError, match="expected a robot file"):
        load_robot_type(make(tmp_path, "x.wld", "floor 1 1"))


def test_load_types_by_builtin_name():
    assert load_robot_type("s4").name == "S4"
    assert load_robot_type("LabBot").lidar is not None
    assert load_object_type("can").name == "Can"
    with pytest.raises(SceneError, match="unknown built-in robot type 'R2D2'"):
        load_robot_type("R2D2")


def test_scene_error_lists_every_problem_with_file_line_column(tmp_path):
    scene = make(tmp_path, "s.sim", "marker 1\nS4 1 x 0\nworld a b\n")
    with pytest.raises(SceneError) as caught:
        load_scene(scene)
    lines = str(caught.value).splitlines()
    assert [line.split(": error: ")[0] for line in lines] == [f"{scene}:1:1", f"{scene}:2:6", f"{scene}:3:1"]


def test_the_default_scene_has_a_clear_run_ahead():
    scene = load_scene(DEFAULT_SCENE)
    assert scene.warnings == ()
    (robot,) = scene.robots
    assert robot.pose == Pose(500, 500, 0) and robot.type_name == "S4"
    assert (scene.world.floor_width, scene.world.floor_height) == (2000, 2000)
    s4 = scene.robot_types["S4"]
    # the footprint swept while driving 1300 mm ahead and turning on the spot at the start
    x0, x1 = 500 - s4.length, 500 + 1300 + s4.length / 2
    y0, y1 = 500 - s4.length, 500 + s4.length
    for wall in scene.world.walls:
        for i in range(101):
            x = wall.x1 + (wall.x2 - wall.x1) * i / 100
            y = wall.y1 + (wall.y2 - wall.y1) * i / 100
            assert not (x0 <= x <= x1 and y0 <= y <= y1), wall


FUZZ_SUFFIXES = (".sim", ".wld", ".maz", ".robi", ".esObj", ".json")


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(FUZZ_SUFFIXES), st.binary(max_size=300) | st.text(max_size=300).map(str.encode))
def test_any_file_content_raises_only_scene_errors(suffix, content):
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / ("fuzz" + suffix)
        path.write_bytes(content)
        for load in (load_scene, load_robot_type, load_object_type):
            try:
                load(path)
            except SceneError as e:
                assert e.diagnostics and all(d.kind in ("error", "warning") for d in e.diagnostics)


@settings(max_examples=150, deadline=None)
@given(st.sampled_from([t for t in corpus_texts("sim")]), st.text(max_size=60))
def test_scenes_with_odd_references_raise_only_scene_errors(scene_text, reference):
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "odd.sim"
        path.write_text(
            scene_text + "\nworld " + json.dumps(reference) + "\nrobot " + json.dumps(reference) + "\n",
            encoding="utf-8",
        )
        try:
            load_scene(path)
        except SceneError:
            pass


def test_deeply_nested_json_is_an_error(tmp_path):
    path = tmp_path / "deep.json"
    path.write_text('{"format": "eyesim.world", "version": 1, "walls": ' + "[" * 5000 + "]" * 5000 + "}")
    with pytest.raises(SceneError):
        load_scene(path)


def test_a_file_named_like_a_builtin_does_not_hide_it(tmp_path):
    make(tmp_path, "S4.robi", "dialect eyesim\nname S4Bot\nwheel 60 3600 1000 100\n")
    scene = make(tmp_path, "s.sim", "robot S4.robi\nS4Bot 1 1 0\nS4 2 2 0\n")
    loaded = load_scene(scene)
    assert [r.type_name for r in loaded.robots] == ["S4Bot", "S4"]
    assert loaded.robot_types["S4"].wheels.diameter == 54


def test_a_definition_named_like_a_builtin_replaces_it(tmp_path):
    make(tmp_path, "mine.robi", "dialect eyesim\nname S4\nwheel 60 3600 1000 100\n")
    loaded = load_scene(make(tmp_path, "s.sim", "robot mine.robi\nS4 2 2 0\n"))
    assert loaded.robot_types["S4"].wheels.diameter == 60


def test_relative_textures_are_found_in_the_folders_above_as_eyesim_found_them(tmp_path):
    # the corpus' worlds/worlds/Soccer1998.wld names ../textures/soccer.png, in textures/ beside worlds/
    scene = load_scene(CORPUS / "ASAX21__VRRoboticProject/Test Assets/examples/drivemodes/Diff.sim")
    assert scene.world.floor_texture == str(CORPUS / "ASAX21__VRRoboticProject/Test Assets/textures/soccer.png")
    # a world elsewhere naming a texture that sits in the scene's own folder
    image = make(tmp_path, "lab/textures/floor.png", "x")
    make(tmp_path, "shared/worlds/deep/down/arena.wld", "floor 1000 1000\nfloor_texture textures/floor.png\n")
    sim = make(tmp_path, "lab/run.sim", "world ../shared/worlds/deep/down/arena.wld\n")
    assert load_scene(sim).world.floor_texture == str(image)
