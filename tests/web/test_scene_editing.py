"""The scene editor's server side: paths confined to the scene roots, edit operations on the
scene description, and saving as .sim/.wld or JSON that loads back as the same scene."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.corpus import CORPUS  # noqa: E402
from support.programs import eyesim_command  # noqa: E402

from eyesim.protocol.channel_schema import route_request_problem
from eyesim.scene import load_scene
from eyesim.scene.builtins import DEFAULT_SCENE
from eyesim.scene.editing import Draft, EditError, apply, saved_files
from eyesim.web.scene_files import FileAccessError, SceneRoots


@pytest.fixture
def roots(tmp_path):
    (tmp_path / "work" / "labs").mkdir(parents=True)
    (tmp_path / "outside").mkdir()
    return SceneRoots([("work", tmp_path / "work", True)])


def test_paths_are_confined_to_the_roots(roots, tmp_path):
    (tmp_path / "outside" / "secret.sim").write_text("S4 1 1 0\n")
    (tmp_path / "work" / "labs" / "a.sim").write_text("S4 1 1 0\n")
    (tmp_path / "work" / "escape").symlink_to(tmp_path / "outside")
    assert roots.locate(0, "labs/a.sim") == (tmp_path / "work" / "labs" / "a.sim").resolve()
    assert roots.locate(0, "labs\\a.sim") == (tmp_path / "work" / "labs" / "a.sim").resolve()
    for bad, reason in [
        ("../outside/secret.sim", "'..'"),
        ("labs/../../outside/secret.sim", "'..'"),
        (str(tmp_path / "outside" / "secret.sim"), "absolute"),
        ("C:/x.sim", "absolute"),
        ("escape/secret.sim", "symbolic link"),
        ("", "relative"),
        ("a\0b", "NUL"),
    ]:
        with pytest.raises(FileAccessError, match=reason):
            roots.locate(0, bad)
    with pytest.raises(FileAccessError, match="no scene root"):
        roots.locate(1, "labs/a.sim")
    with pytest.raises(FileAccessError, match="no scene root"):
        roots.locate(True, "labs/a.sim")
    # the listing does not follow the link out either
    assert roots.scene_files() == [{"root": 0, "path": "labs/a.sim"}]


def test_listing_finds_scene_files_and_json_scenes_by_search_words(roots, tmp_path):
    labs = tmp_path / "work" / "labs"
    (labs / "maze.maz").write_text("S\n")
    (labs / "room.wld").write_text("floor 1000 1000\n")
    (labs / "scene.json").write_text('{"format": "eyesim.scene", "version": 1, "placements": []}')
    (labs / "package.json").write_text('{"name": "not a scene"}')
    (labs / "notes.txt").write_text("hello")
    listed = [f["path"] for f in roots.scene_files()]
    assert listed == ["labs/maze.maz", "labs/room.wld", "labs/scene.json"]
    assert [f["path"] for f in roots.scene_files("LABS ro")] == ["labs/room.wld"]


def draft_of(path) -> Draft:
    return Draft.of_scene(load_scene(path))


def test_edits_build_the_scene_through_the_loader():
    draft = draft_of(DEFAULT_SCENE)
    draft = apply(draft, {"op": "add-robot", "type": "labbot", "x": 1500, "y": 400, "phi": 450}, None)
    draft = apply(draft, {"op": "add-object", "type": "Can", "x": 1000, "y": 1000, "phi": 0}, None)
    draft = apply(draft, {"op": "add-marker", "x": 300, "y": 1700, "color": [0, 0, 255]}, None)
    walls = len(draft.world.walls)
    draft = apply(draft, {"op": "add-wall", "x1": 200, "y1": 1200, "x2": 800, "y2": 1200}, None)
    draft = apply(draft, {"op": "move", "kind": "robot", "index": 0, "x": 700, "y": 600, "phi": -90}, None)
    draft = apply(draft, {"op": "duplicate", "kind": "object", "index": 0}, None)
    draft = apply(draft, {"op": "delete", "kind": "wall", "index": 0}, None)
    draft = apply(draft, {"op": "set-floor", "width": 3000, "height": 2500}, None)
    scene = draft.scene()
    assert [(r.type_name, r.pose.x, r.pose.y, r.pose.phi) for r in scene.robots] == [
        ("S4", 700, 600, -90),
        ("LabBot", 1500, 400, 90),
    ]
    assert [(o.type_name, o.pose.x) for o in scene.objects] == [("Can", 1000), ("Can", 1150)]
    assert scene.markers[-1].color == (0, 0, 255, 255)
    assert len(scene.world.walls) == walls and scene.world.walls[-1].y1 == 1200
    assert (scene.world.floor_width, scene.world.floor_height) == (3000, 2500)


@pytest.mark.parametrize(
    "op, message",
    [
        ({"op": "add-robot", "type": "R2D2", "x": 1, "y": 1}, "unknown robot type 'R2D2'"),
        ({"op": "move", "kind": "robot", "index": 5, "x": 1, "y": 1}, "no robot number 5"),
        ({"op": "move", "kind": "wall", "index": 0, "x": 1, "y": 1}, "move: field 'x1' is missing"),
        ({"op": "add-wall", "x1": 5, "y1": 5, "x2": 5, "y2": 5}, "no length"),
    ],
)
def test_edits_the_scene_cannot_take_are_refused_with_the_reason(op, message):
    with pytest.raises(EditError, match=message):
        apply(draft_of(DEFAULT_SCENE), op, None)


@pytest.mark.parametrize(
    "op, message",
    [
        ({"op": "add-object", "type": "Can", "x": "1", "y": 1}, "add-object: x must be a number, not '1'"),
        (
            {"op": "add-object", "type": "Can", "x": 1e9, "y": 1},
            "add-object: x must be a number from -100000 to 100000",
        ),
        (
            {"op": "delete", "kind": "tree", "index": 0},
            "delete: kind must be one of 'robot', 'object', 'marker', 'wall'",
        ),
        ({"op": "set-floor", "width": 10, "height": 1000}, "set-floor: width must be a number from 100 to 100000"),
        ({"op": "add-marker", "x": 1, "y": 1, "color": [1, 2]}, "add-marker: color must have at least 3 items"),
        ({"op": "move", "kind": "robot", "index": -1}, "move: index must be a whole number at least 0"),
        ({"op": "explode"}, "op must be one of 'add-robot', "),
        ({"editing": "yes"}, "editing must be true or false, not 'yes'"),
        ({}, "field 'editing' is missing"),
    ],
)
def test_malformed_edits_are_refused_by_the_schema(op, message):
    """The edit route checks every body against SceneEdit before the edit is tried."""
    assert message in route_request_problem("POST /scenes/edit", op)


def test_a_robi_file_under_the_roots_becomes_a_robot_type(roots, tmp_path):
    shutil.copy(DEFAULT_SCENE.parent.parent / "robots" / "S4.robi", tmp_path / "work" / "Mine.robi")
    draft = apply(
        draft_of(DEFAULT_SCENE),
        {"op": "add-robot", "file": {"root": 0, "path": "Mine.robi"}, "x": 900, "y": 900},
        lambda place: roots.locate(place["root"], place["path"]),
    )
    scene = draft.scene()
    assert len(scene.robots) == 2
    assert draft.robot_files == (str((tmp_path / "work" / "Mine.robi").resolve()),)


def same_scene(a, b) -> None:
    assert [(r.type_name, r.pose, Path(r.program).resolve() if r.program else None) for r in a.robots] == [
        (r.type_name, r.pose, Path(r.program).resolve() if r.program else None) for r in b.robots
    ]
    assert [(o.type_name, o.pose) for o in a.objects] == [(o.type_name, o.pose) for o in b.objects]
    assert a.markers == b.markers and a.settings == b.settings
    assert a.world.walls == b.world.walls
    assert (a.world.floor_width, a.world.floor_height) == (b.world.floor_width, b.world.floor_height)


@pytest.mark.parametrize("as_json", [False, True])
def test_a_corpus_scene_edited_and_saved_loads_back_the_same_and_passes_check(tmp_path, as_json):
    source = tmp_path / "corpus"
    shutil.copytree(CORPUS / "23082899__distBug", source)
    program = tmp_path / "out" / "drive.py"
    program.parent.mkdir()
    program.write_text("print('hi')\n")
    draft = draft_of(source / "obstacles4k.sim")
    draft = apply(draft, {"op": "add-robot", "type": "S4", "x": 1000, "y": 700, "phi": 30}, None)
    draft = apply(draft, {"op": "set-program", "index": 1, "program": {"path": "drive.py"}}, lambda place: program)
    draft = apply(draft, {"op": "add-object", "type": "Soccer", "x": 2000, "y": 2000.5}, None)
    draft = apply(draft, {"op": "add-wall", "x1": 100, "y1": 3000, "x2": 1100.25, "y2": 3000}, None)
    edited = draft.scene()
    target = tmp_path / "out" / ("saved.json" if as_json else "saved.sim")
    files = saved_files(draft, target, as_json)
    assert set(files) == {target, tmp_path / "out" / ("saved.world.json" if as_json else "saved.wld")}
    for path, text in files.items():
        path.write_text(text)
    if not as_json:
        assert "drive.py" in files[target] and "world saved.wld" in files[target]
    same_scene(load_scene(target), edited)
    check = subprocess.run(eyesim_command("check", str(target)), capture_output=True, text=True)
    assert check.returncode == 0, check.stdout + check.stderr


def test_an_unchanged_world_is_named_not_copied(tmp_path):
    source = tmp_path / "corpus"
    shutil.copytree(CORPUS / "23082899__distBug", source)
    draft = apply(draft_of(source / "obstacles4k.sim"), {"op": "add-object", "type": "Can", "x": 900, "y": 900}, None)
    files = saved_files(draft, source / "copy.sim", False)
    assert list(files) == [source / "copy.sim"]
    assert "world obstacles4k.wld" in files[source / "copy.sim"]
    (source / "copy.sim").write_text(files[source / "copy.sim"])
    same_scene(load_scene(source / "copy.sim"), draft.scene())
    assert os.path.exists(source / "obstacles4k.wld")


def test_a_maze_scene_with_a_drawn_wall_is_saved_as_a_world_of_its_own(tmp_path):
    source = tmp_path / "lab7"
    shutil.copytree(CORPUS / "met4000__AUTO4508-labs" / "lab7", source)
    original = load_scene(source / "maze.sim")
    draft = apply(Draft.of_scene(original), {"op": "add-wall", "x1": 10, "y1": 10, "x2": 300, "y2": 10}, None)
    assert draft.world_file is None and draft.robots[0].pose == original.robots[0].pose  # the start S, placed
    files = saved_files(draft, tmp_path / "mine.sim", False)
    for path, text in files.items():
        path.write_text(text)
    saved = load_scene(tmp_path / "mine.sim")
    same_scene(saved, draft.scene())
    assert len(saved.world.walls) == len(original.world.walls) + 1
    check = subprocess.run(eyesim_command("check", str(tmp_path / "mine.sim")), capture_output=True, text=True)
    assert check.returncode == 0, check.stdout + check.stderr
