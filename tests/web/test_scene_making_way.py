"""The scene editor's server side, second part: a robot or object put down on a wall or another
body makes way (it alone moves, to the nearest free place), a wall drawn across a body leaves the
body where the loader put it, and the inspector's wall and marker properties; so that a scene
saved after any of these loads back without `overlap` warnings."""

import pytest

from eyesim.protocol.channel_schema import route_request_problem
from eyesim.scene import load_scene
from eyesim.scene.editing import Draft, EditError, apply, make_way, placed_body, saved_files, settled

# A 2 m floor with one wall across the middle (y = 1000) and two S4s and a can below it.
SCENE = """world room.wld
S4 500 500 0
S4 1500 500 0
Can 1000 300 0
"""


@pytest.fixture
def room(tmp_path):
    (tmp_path / "room.wld").write_text("floor 2000 2000\n0 1000 2000 1000\n")
    (tmp_path / "room.sim").write_text(SCENE)
    return tmp_path


def edited(draft: Draft, op: dict) -> tuple[Draft, str]:
    """An edit as the workspace makes it: applied, the body put down makes way, then settled."""
    draft = apply(draft, op, None)
    body = placed_body(draft, op)
    moved = ""
    if body is not None:
        draft, moved = make_way(draft, draft.scene(), *body)
    return settled(draft, draft.scene()), moved


def poses(draft: Draft) -> list[tuple[float, float]]:
    return [(r.pose.x, r.pose.y) for r in draft.robots]


def test_a_robot_dropped_on_another_moves_clear_and_the_other_stays(room):
    draft = Draft.of_scene(load_scene(room / "room.sim"))
    # robot 1 onto robot 2: the loader alone would push robot 2 (placed later) away
    draft, moved = edited(draft, {"op": "move", "kind": "robot", "index": 0, "x": 1510, "y": 510, "phi": 0})
    assert poses(draft)[1] == (1500, 500)
    assert poses(draft)[0] != (1510, 510)
    assert moved.startswith("Robot 1 (S4) overlapped robot 'S4': moved to (")
    assert draft.scene().warnings == ()


def test_a_robot_dropped_into_a_wall_moves_out_of_it(room):
    draft = Draft.of_scene(load_scene(room / "room.sim"))
    draft, moved = edited(draft, {"op": "move", "kind": "robot", "index": 1, "x": 1500, "y": 990, "phi": 90})
    x, y = poses(draft)[1]
    assert x == 1500 and y < 990
    assert "overlapped the wall from (0, 1000) to (2000, 1000)" in moved
    assert draft.scene().warnings == ()


def test_an_object_added_on_a_robot_moves_clear_and_the_robot_stays(room):
    draft = Draft.of_scene(load_scene(room / "room.sim"))
    draft, moved = edited(draft, {"op": "add-object", "type": "Can", "x": 500, "y": 500})
    assert poses(draft)[0] == (500, 500)
    assert moved.startswith("Object 2 (Can) overlapped robot 'S4'")
    assert draft.scene().warnings == ()


def test_a_wall_drawn_across_a_robot_leaves_it_where_the_loader_put_it_and_the_save_loads_clean(room):
    draft = Draft.of_scene(load_scene(room / "room.sim"))
    draft, moved = edited(draft, {"op": "add-wall", "x1": 0, "y1": 500, "x2": 1000, "y2": 500})
    assert moved == "" and poses(draft)[0] != (500, 500)
    for path, text in saved_files(draft, room / "saved.sim", as_json=False).items():
        path.write_text(text)
    again = load_scene(room / "saved.sim")
    assert [d.code for d in again.warnings] == []
    assert [(r.pose.x, r.pose.y) for r in again.robots] == poses(draft)


def test_no_free_place_is_refused_with_the_reason(room):
    # S4s (180 x 150 mm) 10 mm apart, far further than the search for a free place goes
    (room / "crowd.sim").write_text(
        "".join(f"S4 {x} {y} 0\n" for x in range(380, 2700, 190) for y in range(540, 2600, 160))
    )
    draft = Draft.of_scene(load_scene(room / "crowd.sim"))
    with pytest.raises(EditError, match=r"Robot 1 \(S4\) at \(1525, 1530\) overlaps robot 'S4'.*no free place"):
        edited(draft, {"op": "move", "kind": "robot", "index": 0, "x": 1525, "y": 1530, "phi": 0})


def test_the_inspector_sets_a_walls_size_and_colour_and_a_markers_colour(room):
    draft = Draft.of_scene(load_scene(room / "room.sim"))
    draft = apply(draft, {"op": "add-marker", "x": 200, "y": 1500, "color": [255, 0, 0, 128]}, None)
    draft = apply(
        draft,
        {
            "op": "set-properties",
            "kind": "wall",
            "index": 0,
            "x2": 1800,
            "thickness": 40,
            "height": 120,
            "color": [10, 200, 30],
        },
        None,
    )
    draft = apply(draft, {"op": "set-properties", "kind": "marker", "index": 0, "x": 250, "color": [0, 0, 255]}, None)
    assert draft.items()["walls"] == [
        {"x1": 0, "y1": 1000, "x2": 1800, "y2": 1000, "thickness": 40, "height": 120, "color": [10, 200, 30]}
    ]
    assert draft.items()["markers"] == [{"x": 250, "y": 1500, "color": [0, 0, 255, 128]}]
    for path, text in saved_files(draft, room / "styled.sim", as_json=False).items():
        path.write_text(text)
    wall = load_scene(room / "styled.sim").world.walls[0]
    assert (wall.x2, wall.thickness, wall.height, wall.color) == (1800, 40, 120, (10, 200, 30))


@pytest.mark.parametrize(
    "op, message",
    [
        ({"op": "set-properties", "kind": "wall", "index": 3, "height": 10}, "no wall number 3"),
        ({"op": "set-properties", "kind": "wall", "index": 0, "x": 10}, "a wall has x1, y1, x2, y2"),
        ({"op": "set-properties", "kind": "wall", "index": 0, "x1": 2000}, "no length"),
    ],
)
def test_inspector_edits_that_cannot_be_made_say_why(room, op, message):
    with pytest.raises(EditError, match=message):
        apply(Draft.of_scene(load_scene(room / "room.sim")), op, None)


@pytest.mark.parametrize(
    "op, message",
    [
        ({"op": "set-properties", "kind": "robot", "index": 0}, "kind must be one of 'wall', 'marker'"),
        ({"op": "set-properties", "kind": "wall", "index": 0, "height": 0}, "height must be a number from 1 to 10000"),
        ({"op": "set-properties", "kind": "wall", "index": 0, "color": [1, 2, 300]}, "color[2] must be"),
    ],
)
def test_malformed_inspector_edits_are_refused_by_the_schema(op, message):
    assert message in route_request_problem("POST /scenes/edit", op)
