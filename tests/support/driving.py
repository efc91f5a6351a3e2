"""Headless runs of scenes with our example robots, and the true poses they recorded."""

from __future__ import annotations

from pathlib import Path

from support.programs import read_trajectory, run_headless
from support.rooms import Run, square_room, write_scene

from eyesim.scene import builtins

EXAMPLE_ROBOTS = builtins.ROBOTS_DIR


class Drive(Run):
    """A finished run with the trajectory it recorded (true poses every 10 ms, metres)."""

    def __init__(self, result, trajectory: dict[int, list[dict]]):
        super().__init__(result)
        self.trajectory = trajectory

    def pose_at(self, robot: int, time_ms: int) -> dict:
        """The last recorded pose of `robot` at or before a simulation time in ms (rows come every 10 ms)."""
        rows = [row for row in self.trajectory[robot] if row["time_s"] * 1000 <= time_ms + 1e-6]
        assert rows, f"no pose of robot {robot} recorded by {time_ms} ms"
        return rows[-1]

    def marks(self, robot: int) -> dict[str, dict]:
        """The true pose at each `mark <name> <ms>` line the robot's program printed."""
        return {
            line.split()[1]: self.pose_at(robot, int(line.split()[2]))
            for line in self.lines(robot)
            if line.startswith("mark ")
        }


def drive_scene(
    directory: Path,
    build,
    placements: list[str],
    robot_programs: dict[int, str],
    robots=(),
    extra=(),
    size: int = 3000,
    wall_height: int = 300,
    timeout: float = 120,
) -> Drive:
    """Runs a headless scene in `directory`: a walled square floor of `size` mm, our example robots
    `robots` (file names in eyesim/data/robots) loaded, `placements` and `extra` .sim lines, and the
    programs (names in tests/robot/programs) on the robots; returns the Drive."""
    world = square_room(size)
    if wall_height != 300:
        world = [line if line.startswith("floor") else f"{line} 10 {wall_height}" for line in world]
    lines = [f"robi {EXAMPLE_ROBOTS / name}.robi" for name in robots] + list(extra)
    scene = write_scene(directory, world, placements, extra=lines)
    options = [arg for robot, name in robot_programs.items() for arg in ("--program", f"{robot}={build(name)}")]
    result = run_headless(str(scene), *options, "--record", "path.csv", cwd=directory, timeout=timeout)
    assert result.returncode == 0, result.stdout + result.stderr
    return Drive(result, read_trajectory(directory / "path.csv"))
