"""Manipulators: the end effector goes where the DH table says, the gripper carries a can, and a
mobile base with an arm drives and picks in one program."""

import math

import numpy as np
import pytest

from eyesim.parts.arm.component import Arm
from support.client import ProgramClient
from support.simulator import running_simulation
from support.worlds import arena_scene, example_robot


def dh(theta: float, d: float, a: float, alpha: float) -> np.ndarray:
    """The standard Denavit-Hartenberg transform of one link (radians, mm)."""
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    return np.array([[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0, sa, ca, d], [0, 0, 0, 1]])


def forward_kinematics(robot_type, positions, chassis: np.ndarray) -> np.ndarray:
    """End effector position (mm, world) for servo positions 0..255 of the joints, by the table;
    `chassis` is the robot frame's true pose in the world (4 x 4, mm)."""
    arm = robot_type.arm
    mount = dh(math.radians(arm.heading), 0, 0, 0)  # the arm's base turned by its heading ...
    mount[:3, 3] = [arm.x, arm.y, arm.z]  # ... where it is mounted on the robot
    chain = chassis @ mount
    for joint, position in zip(arm.joints, positions):
        value = joint.min + (joint.max - joint.min) * position / 255
        if joint.kind == "revolute":
            chain = chain @ dh(math.radians(joint.theta + value), joint.d, joint.a, math.radians(joint.alpha))
        else:
            chain = chain @ dh(math.radians(joint.theta), joint.d + value, joint.a, math.radians(joint.alpha))
    return chain[:3, 3]


@pytest.mark.parametrize(
    "name,settings",
    [
        ("Reacher", [(0, 128, 128), (100, 30, 200), (255, 255, 0), (50, 180, 60)]),
        ("Picker", [(128, 128, 128), (64, 200, 40), (255, 20, 250)]),
    ],
)
def test_the_end_effector_is_where_the_dh_table_puts_it(name, settings):
    robot_type = example_robot(name)
    pose = (1000, 1000, 30)
    with running_simulation(arena_scene([(robot_type, pose)], size=2000), "deterministic", expect=(1,)) as (sim, port):
        client = ProgramClient(port)
        client.hello()
        arm = sim.robots[0].component(Arm)
        for setting in settings:
            for servo, position in enumerate(setting, start=1):
                assert client.call("SERVO_SET", servo, position) == (0,)
            client.call("OS_WAIT", 4000)  # slow servos: 360 degrees take 4 s
            # from the chassis' true pose: a mobile base leans a little under its arm
            body = sim.robots[0].body
            chassis = np.eye(4)
            chassis[:3, :3] = sim.world.data.xmat[body].reshape(3, 3)
            chassis[:3, 3] = sim.world.data.xpos[body] * 1000
            expected = forward_kinematics(robot_type, setting, chassis)
            reached = np.array(arm.end_effector()) * 1000
            assert np.linalg.norm(reached - expected) < 1.0, (setting, reached, expected)
        client.close()


def test_the_arm_picks_up_a_can_and_carries_it(drive):
    run = drive(["Reacher 1500 1500 0", "Can 1500 1800 0"], {1: "arm_pick"}, robots=["Reacher"])
    [[x0, y0, z0, phi0]] = run.values(1, "before")
    [[x1, y1, z1, phi1]] = run.values(1, "lifted")
    [[x2, y2, z2, phi2]] = run.values(1, "swung")
    assert (x0, y0, z0) == (1500, 1800, 0)
    assert z1 > 100 and math.hypot(x1 - x0, y1 - y0) < 10  # lifted straight up
    assert z2 > 100 and math.hypot(x2 - x0, y2 - y0) > 300  # carried round with the arm
    # no servo 5, position -1, low above high, no VW on an arm
    assert run.values(1, "errors") == [[1, 1, 1, 1]]


def test_a_mobile_manipulator_drives_and_picks_in_one_program(drive):
    # Picker's gripper points down 197 mm ahead of its centre: after 400 mm it is over the can.
    run = drive(["Picker 500 1000 0", "Can 1097 1000 0"], {1: "picker"}, robots=["Picker"])
    robots, cans = run.values(1, "robot"), run.values(1, "can")
    assert robots[0][0] == 500 and abs(robots[1][0] - 900) <= 5 and abs(robots[2][0] - 600) <= 5
    assert cans[0][:3] == [1097, 1000, 0]
    assert cans[1][2] > 50  # lifted
    assert abs((cans[2][0] - cans[1][0]) - (robots[2][0] - robots[1][0])) <= 10  # and carried back
    assert cans[2][2] > 50
