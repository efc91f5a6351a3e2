"""Submarines driven ahead and astern under water, in-process: the thrusters are driven as the
MOTOR handler drives them and the simulation is stepped, the hull's height and pitch read back."""

from __future__ import annotations

import math

from support.worlds import arena_scene

from eyesim.core.engine import Simulation
from eyesim.scene.description import RobotType

PHASES = ((60, 10.0), (0, 4.0), (-60, 10.0))  # % on the horizontal thrusters, seconds


def pitch_degrees(sim: Simulation, robot) -> float:
    """The hull's pitch, nose down positive."""
    w, x, y, z = sim.world.data.xquat[robot.body]
    return math.degrees(math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x)))))


def under_water_run(
    robot_type: RobotType, ahead: tuple[int, ...], trim: dict[int, float] | None = None, height: float = 0.8
) -> tuple[list[float], list[float]]:
    """Put `height` m above the floor of a 2 m deep pool (20 x 20 m), with the `trim` motors at
    their %: ahead at 60 % on the `ahead` motors for 10 s, 4 s without, astern for 10 s. Returns the
    hull's height (mm) and pitch (degrees) every 0.1 s."""
    sim = Simulation(arena_scene([(robot_type, (3000, 10000, 0))], size=20000, wall_height=2000))
    robot = sim.robots[0]
    robot.set_pose(3.0, 10.0, height, 0.0)
    for motor, percent in (trim or {}).items():
        robot.motors[motor].drive(percent)
    dt = sim.step_us / 1e6
    heights, pitches = [], []
    for percent, seconds in PHASES:
        for motor in ahead:
            robot.motors[motor].drive(percent)
        for step in range(round(seconds / dt)):
            sim.step()
            if step % round(0.1 / dt) == 0:
                heights.append(robot.pose()[2] * 1000)
                pitches.append(pitch_degrees(sim, robot))
    return heights, pitches
