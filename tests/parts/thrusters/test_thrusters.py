"""Thrusters alone, driven through the motor group (MOTORDrive): each pushes along its own axis
with the percentage of its maximum thrust, and only while it is under water."""

from pathlib import Path

import numpy as np
import pytest
from support.connected import connected_program
from support.worlds import arena_scene

from eyesim.parts.thrusters.component import Thrusters
from eyesim.scene import load_robot_type

SURFACE = 1500  # mm: the pool's walls are 1.5 m high and the water fills it to the rim

# A hull with thrusters and nothing else: no buoyancy, no drag.
PROP = """dialect eyesim
drive SUBMARINE
name Prop
size 400 200 200
mass 4 0 0 100
thruster AHEAD 1 -200 0 100  1 0 0  10
thruster UP    2    0 0 100  0 0 1   6
"""


def thrust_on_hull(sim) -> np.ndarray:
    """The force (N, world frame) the actuators put on the robot's free joint now."""
    world, robot = sim.world, sim.robots[0]
    dof = world.model.jnt_dofadr[world.model.body_jntadr[robot.body]]
    return np.array(world.data.qfrc_actuator[dof : dof + 3])


def test_a_thruster_pushes_along_its_axis_with_motor_drive_s_share_under_water_only(tmp_path: Path):
    (tmp_path / "Prop.robi").write_text(PROP)
    scene = arena_scene([(load_robot_type(tmp_path / "Prop.robi"), (1500, 1500, 90))], wall_height=SURFACE)
    with connected_program(scene) as (sim, client):
        assert len(sim.robots[0].components_of(Thrusters)) == 1
        assert client.call("MOTOR_DRIVE", 1, 50) == (0,)
        client.call("OS_WAIT", 10)
        # Heading 90 degrees: the robot's forward axis is the world's +y.
        assert thrust_on_hull(sim) == pytest.approx([0.0, 5.0, 0.0], abs=0.05)
        assert client.call("MOTOR_DRIVE", 1, -100) == (0,)  # negative speeds reverse
        assert client.call("MOTOR_DRIVE", 2, 50) == (0,)
        client.call("OS_WAIT", 10)
        assert thrust_on_hull(sim) == pytest.approx([0.0, -10.0, 3.0], abs=0.05)
        # Lifted out of the pool, the thrusters push on air: nothing.
        assert client.call("SIM_SET_ROBOT", 1, 1500, 1500, SURFACE + 500, 90) == (0,)
        client.call("OS_WAIT", 10)
        assert thrust_on_hull(sim) == pytest.approx([0.0, 0.0, 0.0], abs=1e-9)
