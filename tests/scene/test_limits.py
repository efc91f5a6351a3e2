"""Scene limits (docs/file-formats.md, "Limits"): each fuzzing finding of the reliability issue,
and each limit just past it, is refused with an error naming the limit at its file:line, never a
hang, a MemoryError or a traceback; crowds of bodies are spread or refused; a large legal world
loads and builds. Files are generated here; time bounds are only generous guards against hangs."""

import json
import math
import time
import tracemalloc

import mujoco
import pytest
from support.programs import run_headless

from eyesim.core.engine import Simulation
from eyesim.physics import world as physics_world
from eyesim.scene import SceneError, load_scene, limits
from eyesim.scene.placement import SEARCH_RINGS

ARENA = ["floor 2000 2000", "0 0 2000 0", "2000 0 2000 2000", "2000 2000 0 2000", "0 2000 0 0"]


def write(tmp_path, name, lines):
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return path


def scene_with(tmp_path, placements, world=ARENA):
    write(tmp_path, "room.wld", world)
    return write(tmp_path, "scene.sim", ["world room.wld", *placements])


def refusal(path):
    """The one error of a refused load."""
    with pytest.raises(SceneError) as caught:
        load_scene(path)
    [error] = caught.value.errors
    assert error.code == "limit"
    return error


# -- the findings ----------------------------------------------------------------------------
def test_a_100_mb_one_line_world_is_refused_unread(tmp_path):
    path = tmp_path / "huge.wld"
    with open(path, "wb") as f:  # sparse: 100 MB without writing them
        f.seek(100 * 1024 * 1024)
        f.write(b"1")
    tracemalloc.start()
    try:
        error = refusal(path)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert str(error) == f"{path}: error: the file is larger than 4 MB, the limit for a scene file: not read"
    assert peak < 3 * limits.MAX_FILE_BYTES  # read no further than the limit (it took 2.9 GB)


def test_a_world_of_a_million_walls_is_refused_at_once(tmp_path):
    # 10^6 short walls fit in 8 MB; a world this size hung `eyesim check` and `run` for minutes.
    path = tmp_path / "million.wld"
    path.write_bytes(b"0 0 1 1\n" * 1_000_000)
    start = time.perf_counter()
    error = refusal(path)
    assert time.perf_counter() - start < 10  # a guard against a hang; it takes milliseconds
    assert "larger than 4 MB, the limit for a scene file" in error.message


def test_300_robots_on_one_spot_are_refused_by_the_robot_limit(tmp_path):
    path = scene_with(tmp_path, ["S4 1000 1000 0"] * 300)
    error = refusal(path)
    assert (error.location.line, error.message) == (1 + 257, "more than 256 robots, the limit for a scene")


def test_200_robots_on_one_spot_fill_the_room_round_it_and_the_next_is_refused(tmp_path):
    path = scene_with(tmp_path, ["S4 1000 1000 0"] * 200)
    error = refusal(path)
    # in a 2 m room only so many S4s fit within SEARCH_RINGS of their sizes round the spot
    assert error.location.line > 1 + 20
    assert error.message.startswith("robot 'S4' at (1000, 1000) overlaps robot 'S4' (line ")
    assert f"no free place within {SEARCH_RINGS} of its sizes" in error.message
    assert "the limit for overlapping placements" in error.message


def test_1000_cans_on_one_spot_are_refused_past_the_room_round_it(tmp_path):
    path = scene_with(tmp_path, ["Can 1000 1000 0"] * 1000, world=["floor 4000 4000"])
    start = time.perf_counter()
    error = refusal(path)
    assert time.perf_counter() - start < 30  # a guard; it takes about a second
    # the first can stays, (2 * SEARCH_RINGS + 1)^2 - 1 more fit round it, the next is refused
    assert error.location.line == 1 + (2 * SEARCH_RINGS + 1) ** 2 + 1
    assert "object 'Can' at (1000, 1000) overlaps object 'Can' (line " in error.message


def test_a_very_long_program_name_is_refused_at_its_line(tmp_path):
    path = scene_with(tmp_path, ["S4 500 500 0", "S4 1500 500 0 " + "a" * 5000 + ".py"])
    error = refusal(path)
    assert (error.location.line, error.location.column) == (3, 1)
    assert error.message == (
        "file name '" + "a" * 57 + "...' is 5003 bytes long, more than 4096, the limit for a file name"
    )


def test_a_folder_name_past_the_file_systems_limit_is_refused(tmp_path):
    path = scene_with(tmp_path, ["S4 500 500 0 " + "x" * 300 + "/drive.py"])
    assert "has a folder or file name of 300 bytes, more than 255" in refusal(path).message


def test_eyesim_run_with_a_too_long_program_name_says_so_without_a_traceback(tmp_path):
    scene = scene_with(tmp_path, ["S4 500 500 0"])
    result = run_headless(str(scene), "--until", "0.01", "--program", "1=" + "b" * 5000, cwd=tmp_path, timeout=60)
    assert "Traceback" not in result.stderr
    assert "eyesim: program not found: bbbbbbbb" in result.stdout + result.stderr
    assert "(File name too long)" in result.stdout + result.stderr


# -- each limit, just past it ----------------------------------------------------------------
def test_a_line_past_the_limit_is_refused_at_its_line(tmp_path):
    path = write(tmp_path, "long.wld", ["floor 1000 1000", "0 0 1 " + "1" * limits.MAX_LINE_CHARS])
    error = refusal(path)
    assert error.location.line == 2 and f"more than {limits.MAX_LINE_CHARS}, the limit for a line" in error.message


def test_a_file_with_too_many_lines_is_refused_at_the_first_line_past_it(tmp_path):
    path = write(tmp_path, "many.wld", ["pop"] * (limits.MAX_LINES + 1))
    error = refusal(path)
    assert error.location.line == limits.MAX_LINES + 1
    assert error.message == (
        f"the file has {limits.MAX_LINES + 1} lines, more than {limits.MAX_LINES}, the limit for a scene file: not read"
    )


def test_a_world_at_the_wall_limit_loads_and_one_more_wall_is_refused_at_its_line(tmp_path):
    walls = [f"{i % 200 * 50} {i // 200 * 50} {i % 200 * 50 + 20} {i // 200 * 50}" for i in range(limits.MAX_WALLS)]
    assert len(load_scene(write(tmp_path, "full.wld", walls)).world.walls) == limits.MAX_WALLS
    error = refusal(write(tmp_path, "over.wld", ["floor 10000 10000", *walls, "0 0 0 9000", "0 0 9000 0"]))
    assert (error.location.line, error.message) == (
        limits.MAX_WALLS + 2,
        "more than 20000 walls, the limit for a world",
    )


def test_a_maze_past_the_wall_limit_is_refused(tmp_path):
    # every '|' of a row is a wall of its own when the rows between are empty
    bars = "| " * 201
    rows = [bars if n % 2 == 0 else "" for n in range(201)]
    error = refusal(write(tmp_path, "big.maz", rows))
    assert error.message == "more than 20000 walls, the limit for a world"


def test_a_json_world_past_the_wall_limit_is_refused_before_its_schema_is_checked(tmp_path):
    walls = [
        {"x1": i % 300 * 10, "y1": i // 300 * 10, "x2": i % 300 * 10 + 5, "y2": i // 300 * 10}
        for i in range(limits.MAX_WALLS + 1)
    ]
    path = tmp_path / "walls.json"
    path.write_text(json.dumps({"format": "eyesim.world", "version": 1, "walls": walls}))
    start = time.perf_counter()
    error = refusal(path)
    assert time.perf_counter() - start < 10  # a guard: validating 100 000 walls took 11 s
    assert (error.location.line, error.message) == (1, "more than 20000 walls, the limit for a world")


def test_robots_past_the_limit_are_refused_at_the_first_one_too_many(tmp_path):
    robots = [f"S4 {150 + 300 * (i % 20)} {150 + 300 * (i // 20)} 0" for i in range(limits.MAX_ROBOTS + 1)]
    error = refusal(scene_with(tmp_path, robots, world=["floor 6000 6000"]))
    assert error.location.line == 1 + limits.MAX_ROBOTS + 1


def test_objects_past_the_limit_are_refused_at_the_first_one_too_many(tmp_path):
    cans = [f"Can {100 + 100 * (i % 50)} {100 + 100 * (i // 50)} 0" for i in range(limits.MAX_OBJECTS + 1)]
    error = refusal(scene_with(tmp_path, cans, world=["floor 6000 6000"]))
    assert (error.location.line, error.message) == (
        1 + limits.MAX_OBJECTS + 1,
        "more than 2000 objects, the limit for a scene",
    )


def test_markers_past_the_limit_are_refused(tmp_path):
    markers = [f"marker {i % 100 * 10} {i // 100 * 10}" for i in range(limits.MAX_MARKERS + 1)]
    assert refusal(scene_with(tmp_path, markers)).message == "more than 10000 markers, the limit for a scene"


def test_eyesim_check_names_the_limit_and_exits_1(tmp_path, capsys):
    from eyesim.scene import cli

    path = write(tmp_path, "long.wld", ["floor 1000 1000", "x" * (limits.MAX_LINE_CHARS + 1)])
    args = type("Args", (), {"files": [str(path)]})
    assert cli.run_check(args) == 1
    out = capsys.readouterr().out
    assert f"{path}:2: error: the line is 10001 characters long, more than 10000" in out


# -- what stays legal -------------------------------------------------------------------------
def test_100_robots_on_one_spot_are_spread_round_it_and_start(tmp_path):
    scene = load_scene(scene_with(tmp_path, ["S4 1000 1000 0"] * 100))
    moved = [w for w in scene.warnings if w.code == "overlap"]
    assert len(moved) == 99 and "robot 'S4' at (1000, 1000) overlaps robot 'S4' (line 2): moved to" in moved[0].message
    spots = {(r.pose.x, r.pose.y) for r in scene.robots}
    assert len(spots) == 100 and (1000, 1000) in spots
    sim = Simulation(scene)
    for _ in range(100):
        sim.step()
    data = sim.world.data
    assert data.warning[mujoco.mjtWarning.mjWARN_CONTACTFULL].number == 0
    assert data.warning[mujoco.mjtWarning.mjWARN_CNSTRFULL].number == 0
    for robot, placement in zip(sim.robots, scene.robots):  # standing where they were put
        x, y, z, _ = robot.pose_mm()
        assert math.hypot(x - placement.pose.x, y - placement.pose.y) < 5 and abs(z) < 5


def test_mujocos_arena_is_sized_from_the_scene_and_holds_a_packed_crowd(tmp_path):
    # 121 cans packed round one spot, all touching the floor: MuJoCo's own default would reserve
    # hundreds of MB for this and grows with the square of the bodies
    scene = load_scene(scene_with(tmp_path, ["Can 1000 1000 0"] * 121))
    sim = Simulation(scene)
    model = sim.world.model
    assert model.narena == physics_world.ARENA_BASE + physics_world.ARENA_PER_BODY * model.nbody
    assert model.narena < 50 * 1024 * 1024
    for _ in range(50):
        sim.step()
    assert sim.world.data.warning[mujoco.mjtWarning.mjWARN_CNSTRFULL].number == 0
    assert sim.world.data.maxuse_arena < model.narena / 2


def test_a_world_of_10000_walls_loads_and_builds_in_seconds(tmp_path):
    walls = [f"{i % 100 * 100} {i // 100 * 100} {i % 100 * 100 + 50} {i // 100 * 100}" for i in range(10_000)]
    path = scene_with(tmp_path, ["S4 25 50 0"], world=["floor 10000 10000", *walls])
    start = time.perf_counter()
    sim = Simulation(load_scene(path))
    assert time.perf_counter() - start < 30  # a guard; about a second (bench/bench_scene_load.py)
    assert sim.world.model.ngeom >= 10_000
