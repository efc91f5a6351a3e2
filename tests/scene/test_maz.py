"""The .maz ASCII maze format: geometry, start letters, balls, crates, cell size, odd layouts."""

from hypothesis import given, settings

from eyesim.scene.description import Marker, Pose, StartPosition, Wall
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.lexer import read_text
from eyesim.scene.maz import MazeDocument, maze_world, parse_maz, write_maz
from scene_testing import CORPUS, corpus_texts, mutated, random_text

EXAMPLE = " _______\n|   |   |\n| |___  |\n|s|   r |\n|_______|\n250\n"


def world_of(text):
    diagnostics = Diagnostics()
    maze = parse_maz(text, "m.maz", diagnostics)
    return maze_world(maze, "m.maz", diagnostics), diagnostics


def bbox(world):
    xs = [v for w in world.walls for v in (w.x1, w.x2)]
    ys = [v for w in world.walls for v in (w.y1, w.y2)]
    return min(xs), max(xs), min(ys), max(ys)


def test_documented_example():
    world, diagnostics = world_of(EXAMPLE)
    assert not diagnostics.items
    assert (world.floor_width, world.floor_height) == (1000, 1000)
    assert sorted(world.walls, key=lambda w: (w.x1, w.y1, w.x2, w.y2)) == sorted(
        [
            Wall(0, 0, 1000, 0),
            Wall(250, 500, 750, 500),
            Wall(0, 1000, 1000, 1000),
            Wall(0, 0, 0, 1000),
            Wall(250, 250, 250, 750),
            Wall(500, 750, 500, 1000),
            Wall(1000, 0, 1000, 1000),
        ],
        key=lambda w: (w.x1, w.y1, w.x2, w.y2),
    )
    assert world.start_positions == (StartPosition("s", Pose(125, 375, 90)), StartPosition("r", Pose(625, 375, 0)))


def test_pinned_corpus_maze():
    world, diagnostics = world_of(read_text(CORPUS / "LDY681__AUTO4508-labs/lab7/small.maz"))
    assert not diagnostics.items
    assert len(world.walls) == 15 and bbox(world) == (0, 3600, 0, 3600)
    assert world.start_positions == (StartPosition("S", Pose(360, 360, 90)),)


def test_start_letters_headings_and_upper_case_walls():
    world, _ = world_of(" _________\n|S U D L R|\n|s u d l r|\n")
    headings = {s.letter: s.pose.phi for s in world.start_positions}
    assert headings == {"S": 90, "U": 90, "D": 270, "L": 180, "R": 0, "s": 90, "u": 90, "d": 270, "l": 180, "r": 0}
    # the upper-case row puts a wall under each of its five letters; the lower-case row does not
    under_row_1 = [w for w in world.walls if w.y1 == w.y2 == 360]
    assert under_row_1 == [Wall(0, 360, 1800, 360)]


def test_balls_crates_posts_and_finish():
    world, diagnostics = world_of(" _______\n|o O . |\n|x X F |\n|_______|\n")
    assert not diagnostics.items
    assert [(o.type_name, o.pose) for o in world.objects] == [
        ("Soccer", Pose(180, 900, 0)),
        ("Soccer", Pose(540, 900, 0)),
        ("Crate", Pose(180, 540, 0)),
        ("Crate", Pose(540, 540, 0)),
    ]
    assert world.markers == (Marker(900, 540, (0, 200, 0, 255)),)
    # upper case O and X also put a wall under their cell
    assert Wall(360, 720, 720, 720) in world.walls and Wall(360, 360, 720, 360) in world.walls


def test_cell_size_first_or_last_line_default_and_both():
    assert parse_maz("720\n _\n|_|\n", "m", Diagnostics()).cell_size == 720
    assert parse_maz(" _\n|_|\n100\n\n", "m", Diagnostics()).cell_size == 100
    assert parse_maz(" _\n|_|\n", "m", Diagnostics()).size == 360
    diagnostics = Diagnostics()
    assert parse_maz("720\n _\n|_|\n360\n", "m", diagnostics).cell_size == 360
    assert [d.code for d in diagnostics.items] == ["conflicting-size"]


def test_bad_cell_size_is_an_error():
    diagnostics = Diagnostics()
    parse_maz("-5\n _\n|_|\n", "m", diagnostics)
    assert [(d.kind, d.location.line) for d in diagnostics.items] == [("error", 1)]


def test_rows_starting_with_underscore_and_ragged_lines():
    world, diagnostics = world_of("_____\n|    |\n|  r\n|___|")
    assert not diagnostics.items
    assert all(min(w.x1, w.x2) >= 0 for w in world.walls)  # column 0 '_' is only a corner
    assert world.floor_width == 3 * 360


def test_symbol_in_an_even_column_uses_the_eyesim_rule():
    world, _ = world_of("|______U____S_______|\n1000\n")
    assert [(s.letter, s.pose.x) for s in world.start_positions] == [("U", 3500), ("S", 5500)]


def test_unknown_characters_are_warned_about_once():
    world, diagnostics = world_of(" ___\n|Q Q|\n|___|\n")
    assert [(d.code, d.location.line, d.location.column) for d in diagnostics.items] == [("unknown-character", 2, 2)]


def test_empty_maze_is_an_error():
    diagnostics = Diagnostics()
    parse_maz("\n  \n", "m", diagnostics)
    assert diagnostics.has_errors


def test_write_and_read_back():
    maze = parse_maz(EXAMPLE, "m", Diagnostics())
    again = parse_maz(write_maz(maze), "m", Diagnostics())
    assert (again.rows, again.cell_size) == (maze.rows, maze.cell_size)
    assert write_maz(MazeDocument(("|_|",))) == "|_|\n"


@settings(max_examples=200, deadline=None)
@given(random_text())
def test_random_text_never_crashes(text):
    world_of(text)


@settings(max_examples=200, deadline=None)
@given(mutated(corpus_texts("maz")))
def test_mutated_mazes_never_crash(text):
    world, _ = world_of(text)
    assert world.floor_height is None or world.floor_height >= 0
