"""The sensor examples do their jobs: wall following with PSDs, mapping with the lidar, colour
tracking with the camera (examples/programs, examples/scenes), built and run as a user would."""

import math
import subprocess

import numpy as np
from PIL import Image
from support.programs import eyesim_command, read_trajectory, run_headless
from eyesim.paths import EXAMPLES_DIR

EXAMPLES = EXAMPLES_DIR
# The sensor lab (examples/scenes/sensor_lab.wld): wall centre lines (mm) and their thickness.
ROOM = [((0, 0), (2500, 0)), ((2500, 0), (2500, 2000)), ((2500, 2000), (0, 2000)), ((0, 2000), (0, 0))]
BLOCK = [((650, 550), (950, 550)), ((950, 550), (950, 850)), ((950, 850), (650, 850)), ((650, 850), (650, 550))]
PILLAR = [
    ((1840, 1390), (1960, 1390)),
    ((1960, 1390), (1960, 1510)),
    ((1960, 1510), (1840, 1510)),
    ((1840, 1510), (1840, 1390)),
]
WALLS = [(s, 10) for s in ROOM] + [(s, 20) for s in BLOCK] + [(s, 10) for s in PILLAR]


def to_surface(x: float, y: float) -> float:
    """Distance (mm) from a point to the nearest wall surface of the sensor lab."""
    best = math.inf
    for ((x1, y1), (x2, y2)), thickness in WALLS:
        dx, dy = x2 - x1, y2 - y1
        t = max(0.0, min(1.0, ((x - x1) * dx + (y - y1) * dy) / (dx * dx + dy * dy)))
        best = min(best, math.hypot(x - x1 - t * dx, y - y1 - t * dy) - thickness / 2)
    return best


def run_example(tmp_path, name: str, *args: str):
    program = tmp_path / name
    built = subprocess.run(
        eyesim_command(
            "cc", "-O2", "-Wall", "-Wextra", "-Werror", str(EXAMPLES / "programs" / f"{name}.c"), "-o", str(program)
        ),
        capture_output=True,
        text=True,
    )
    assert built.returncode == 0, built.stderr
    result = run_headless(str(EXAMPLES / "scenes" / f"{name}.sim"), "--program", f"1={program}", *args, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    return result


def test_wall_following_keeps_the_left_wall_at_its_distance(tmp_path):
    run_example(tmp_path, "wall_follow", "--record", "path.csv")
    path = read_trajectory(tmp_path / "path.csv")[1]
    distances = [to_surface(row["x"] * 1000, row["y"] * 1000) for row in path]
    settled = distances[200:]  # after the first 2 s
    # the left PSD (75 mm off the centre) keeps 200 mm: the centre runs about 275 mm from the wall
    assert sum(200 < d < 360 for d in settled) / len(settled) > 0.9
    assert min(distances) > 150  # never close to a crash
    xs, ys = [row["x"] for row in path], [row["y"] for row in path]
    assert max(xs) - min(xs) > 1.8 and max(ys) - min(ys) > 1.3  # all the way round the room


def test_lidar_mapping_draws_the_room(tmp_path):
    run_example(tmp_path, "lidar_map")
    grid = np.asarray(Image.open(tmp_path / "map.pgm"))
    size, cell, start = grid.shape[0], 20, (600, 1500)  # lidar_map.c; the start pose of lidar_map.sim
    rows, cols = np.nonzero(grid == 0)
    points = [
        (start[0] + (c - size // 2 + 0.5) * cell, start[1] + (size - 1 - r - size // 2 + 0.5) * cell)
        for r, c in zip(rows, cols)
    ]
    assert len(points) > 300
    assert sum(to_surface(x, y) < 40 for x, y in points) / len(points) > 0.95  # what it saw is there
    occupied = set(zip(rows.tolist(), cols.tolist()))

    def mapped(x, y):
        col = math.floor((x - start[0]) / cell) + size // 2
        row = size - 1 - (math.floor((y - start[1]) / cell) + size // 2)
        return any((row + i, col + j) in occupied for i in (-2, -1, 0, 1, 2) for j in (-2, -1, 0, 1, 2))

    faces = (
        [(x, 5) for x in range(100, 2400, 50)]
        + [(x, 1995) for x in range(100, 2400, 50)]
        + [(5, y) for y in range(100, 1900, 50)]
        + [(2495, y) for y in range(100, 1900, 50)]
    )
    assert sum(mapped(x, y) for x, y in faces) / len(faces) > 0.8  # and it saw most of the room's walls


def test_colour_tracking_drives_up_to_the_red_pillar(tmp_path):
    result = run_example(tmp_path, "colour_track", "--record", "path.csv")
    assert "arrived: the target fills" in result.stdout
    end = read_trajectory(tmp_path / "path.csv")[1][-1]
    x, y = end["x"] * 1000, end["y"] * 1000
    heading = math.degrees(2 * math.atan2(end["qz"], end["qw"]))
    bearing = math.degrees(math.atan2(1450 - y, 1900 - x))  # to the pillar's centre
    assert abs((heading - bearing + 180) % 360 - 180) < 8
    assert math.hypot(1900 - x, 1450 - y) < 700  # it started 1200 mm away, facing away
