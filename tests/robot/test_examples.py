"""The drive-type examples (examples/scenes and examples/programs) do their jobs, built and run
as a user would."""

import math
import subprocess
from pathlib import Path

import pytest
from support.programs import eyesim_command, read_trajectory, run_headless
from support.rooms import Run
from eyesim.paths import EXAMPLES_DIR

EXAMPLES = EXAMPLES_DIR


def run_example(tmp_path: Path, scene: str, *programs: str) -> tuple[Run, dict]:
    options = []
    for robot, name in enumerate(programs, start=1):
        built = subprocess.run(
            eyesim_command(
                "cc",
                "-O2",
                "-Wall",
                "-Wextra",
                "-Werror",
                str(EXAMPLES / "programs" / f"{name}.c"),
                "-o",
                str(tmp_path / name),
            ),
            capture_output=True,
            text=True,
        )
        assert built.returncode == 0, built.stderr
        options += ["--program", f"{robot}={tmp_path / name}"]
    result = run_headless(str(EXAMPLES / "scenes" / f"{scene}.sim"), *options, "--record", "path.csv", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "warning" not in result.stderr
    return Run(result), read_trajectory(tmp_path / "path.csv")


def test_the_car_slaloms_the_mecanum_robot_drives_a_square_and_the_trolley_pushes_a_crate(tmp_path):
    run, paths = run_example(tmp_path, "drive_types", "car_slalom", "omni_square", "push_crate")
    car = paths[1]
    assert car[-1]["x"] - car[0]["x"] > 1.5  # the car went a long way east
    ys = [row["y"] for row in car]
    assert max(ys) - min(ys) > 0.1  # weaving
    omni = paths[2]
    start, end = omni[0], omni[-1]
    assert math.hypot(end["x"] - start["x"], end["y"] - start["y"]) < 0.02  # the square closed
    assert min(row["x"] for row in omni) < start["x"] - 0.55  # it went 600 mm back ...
    assert min(row["y"] for row in omni) < start["y"] - 0.55  # ... and 600 mm to the right
    assert max(abs(2 * math.atan2(row["qz"], row["qw"])) for row in omni) < math.radians(3)  # never turning
    [[crate_x, crate_y]] = run.values(3, "crate")
    assert crate_x > 900 + 400 and abs(crate_y - 2600) < 30


def test_the_submarine_dives_holds_its_depth_and_surfaces(tmp_path):
    run, paths = run_example(tmp_path, "pool", "submarine_dive")
    [[dived]], [[cruised]], [[surfaced]] = run.values(1, "dived"), run.values(1, "cruised"), run.values(1, "surfaced")
    assert dived == pytest.approx(500, abs=60) and cruised == pytest.approx(500, abs=60)
    assert surfaced <= 0  # the hull's top is out of the water
    path = paths[1]
    assert path[-1]["x"] - path[0]["x"] > 1.0  # it cruised ahead


def test_the_arm_moves_the_can_to_its_new_place(tmp_path):
    run, _ = run_example(tmp_path, "workshop", "pick_and_place")
    [[x, y, z]] = run.values(1, "can")
    assert math.hypot(x - 1790, y - 1421) < 30 and abs(z) < 5  # standing where it was put down
