"""The .wld world format: walls, nested frames, floor, start, texture, and tolerance of bad lines."""

import math

import pytest
from hypothesis import given, settings

from eyesim.scene.description import Pose, Wall
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.lexer import read_text
from eyesim.scene.wld import parse_wld, write_wld
from scene_testing import CORPUS, corpus_texts, mutated, random_text


def parse(text):
    diagnostics = Diagnostics()
    return parse_wld(text, "w.wld", diagnostics), diagnostics


def bbox(world):
    xs = [v for w in world.walls for v in (w.x1, w.x2)]
    ys = [v for w in world.walls for v in (w.y1, w.y2)]
    return min(xs), max(xs), min(ys), max(ys)


def test_classic_world():
    world, diagnostics = parse("; arena\nwidth 3000\nheight 2000\n0 0 3000 0\nposition 300 300 90\n")
    assert (world.floor_width, world.floor_height) == (3000, 2000)
    assert world.walls == (Wall(0, 0, 3000, 0),)
    assert world.start_pose == Pose(300, 300, 90)
    assert not diagnostics.items


def test_vr_saved_world_with_floor_last():
    world, _ = parse("# World file created 01/02/2024 3:04 PM\n\n0 2000 0 0\nfloor 3000 2000")
    assert (world.floor_width, world.floor_height, len(world.walls)) == (3000, 2000, 1)


def test_wall_arities():
    world, diagnostics = parse("0 0 1 0\n0 0 2 0 20 150\n0 0 3 0 18 100 255 255 0\n")
    assert world.walls == (Wall(0, 0, 1, 0), Wall(0, 0, 2, 0, 20, 150), Wall(0, 0, 3, 0, 18, 100, (255, 255, 0)))
    assert not diagnostics.items


def test_push_rotates_then_translates_and_frames_nest():
    world, _ = parse("push 1500 1000 90\n0 0 100 0\npush 100 0 90\n0 0 100 0\npop\n0 0 0 50\npop\n0 0 10 0")
    assert world.walls == (
        Wall(1500, 1000, 1500, 1100),
        Wall(1500, 1100, 1400, 1100),
        Wall(1500, 1000, 1450, 1000),
        Wall(0, 0, 10, 0),
    )


def test_chained_pushes_draw_an_arc():
    world, _ = parse("push 0 0 0\n" + "push 100 0 -5\n0 0 100 0\n" * 18)
    last = world.walls[-1]
    heading = math.degrees(math.atan2(last.y2 - last.y1, last.x2 - last.x1))
    assert heading == pytest.approx(-90)


def test_unbalanced_stacks_are_accepted():
    world, diagnostics = parse("pop\npop\npush 10 10 0\n0 0 1 0\n")
    assert world.walls == (Wall(10, 10, 11, 10),)
    assert not diagnostics.items


def test_inline_semicolon_comments_with_numbers():
    world, diagnostics = parse("width 50510 ;BIGW\npush 3802 8128 90     ; add 1133 to y\n0 0 1685 0  ;add 1685\n")
    assert world.floor_width == 50510
    assert world.walls == (Wall(3802, 8128, 3802, 9813),)
    assert not diagnostics.items


def test_malformed_lines_are_skipped_with_warnings():
    world, diagnostics = parse(
        "ush 500 0 -5\n5000 0 0\n1 2 3 4 5\n0 0 x 1\nwidth -5\nfloor 10\n0 0 1 1 1 1 300 0 0\n1 1 1 1\n0 0 5 0\n"
    )
    assert world.walls == (Wall(0, 0, 5, 0),)
    assert [d.location.line for d in diagnostics.items] == [1, 2, 3, 4, 5, 6, 7, 8]
    assert all(d.kind == "warning" for d in diagnostics.items)
    assert "did you mean 'push'" in diagnostics.items[0].message
    assert "expected 4, 6 or 9 numbers, found 3" in diagnostics.items[1].message
    assert diagnostics.items[3].location.column == 5


def test_texture_and_ball():
    world, _ = parse("floor_texture  ..\\..\\images-videos\\x.png\nball 1350 1028\n")
    assert world.floor_texture == "..\\..\\images-videos\\x.png"
    assert [(o.type_name, o.pose) for o in world.objects] == [("Soccer", Pose(1350, 1028, 0))]


def test_pinned_push_pop_worlds():
    distbug, _ = parse(read_text(CORPUS / "ASAX21__VRRoboticProject/Test Assets/worlds/distbug.wld"))
    assert len(distbug.walls) == 28 and bbox(distbug) == (0, 3000, 0, 3000)
    bigmaze, _ = parse(read_text(CORPUS / "RobertPennefather__GENG5508/labs/lab7/bigmaze.wld"))
    assert len(bigmaze.walls) == 36 and bbox(bigmaze) == (0, 3600, 0, 3600)
    uwa, diagnostics = parse(read_text(CORPUS / "ASAX21__VRRoboticProject/Test Assets/examples/omni/uwa-ee4.wld"))
    assert len(uwa.walls) == 443 and bbox(uwa) == (609, 48949, 210, 15216)
    assert uwa.start_pose == Pose(15800, 5800, 0) and not diagnostics.items


def test_write_and_read_back():
    world, _ = parse(
        "width 3000\nheight 2000\nfloor_texture 'my floor.png'\nposition 1 2 3\nball 5 6\n"
        "0 0 1 0\n0 0 2 0 20 150\n0 0 3 0 18 100 255 255 0\n"
    )
    again, diagnostics = parse(write_wld(world))
    assert again == world and not diagnostics.items


@pytest.mark.parametrize("text", corpus_texts("wld")[:40])
def test_corpus_worlds_write_and_read_back(text):
    world, _ = parse(text)
    again, diagnostics = parse(write_wld(world))
    assert again == world and not diagnostics.items


@settings(max_examples=200, deadline=None)
@given(random_text())
def test_random_text_never_crashes(text):
    world, diagnostics = parse(text)
    assert all(d.kind in ("warning", "error") for d in diagnostics.items)


@settings(max_examples=200, deadline=None)
@given(mutated(corpus_texts("wld")))
def test_mutated_worlds_never_crash(text):
    world, _ = parse(text)
    assert all(math.isfinite(v) for w in world.walls for v in (w.x1, w.y1, w.x2, w.y2))
