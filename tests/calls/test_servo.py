"""The servo group: positions within SERVORange, raw positions, and servos a robot lacks."""

import math

import pytest
from support.client import RemoteError
from support.connected import connected_program
from support.worlds import arena_scene, example_robot

from eyesim.protocol import generated as g
from eyesim.robot.wheels.ackermann_wheels import AckermannDrive
from eyesim.parts.arm.component import Arm, Gripper


def reacher():
    return arena_scene([(example_robot("Reacher"), (1000, 1000, 0))])


def test_servo_range_narrows_what_servo_set_spans_and_raw_ignores_it():
    with connected_program(reacher()) as (sim, client):
        arm = sim.robots[0].component(Arm)
        assert client.call("SERVO_RANGE", 2, 51, 204) == (0,)  # raw 51..204 = -90..90 degrees
        assert client.call("SERVO_SET", 2, 255) == (0,)
        client.call("OS_WAIT", 3000)
        assert math.degrees(arm.joint_values()[1]) == pytest.approx(90, abs=0.2)
        assert client.call("SERVO_SET", 2, 0) == (0,)
        client.call("OS_WAIT", 3000)
        assert math.degrees(arm.joint_values()[1]) == pytest.approx(-90, abs=0.2)
        assert client.call("SERVO_SET_RAW", 2, 255) == (0,)  # the joint's own maximum, 150 degrees
        client.call("OS_WAIT", 4000)
        assert math.degrees(arm.joint_values()[1]) == pytest.approx(150, abs=0.2)


def test_servos_move_at_a_servos_speed():
    with connected_program(reacher()) as (sim, client):
        arm = sim.robots[0].component(Arm)
        client.call("SERVO_SET", 2, 255)  # 0 -> 150 degrees at 90 degrees a second
        client.call("OS_WAIT", 1000)
        assert 60 < math.degrees(arm.joint_values()[1]) < 95
        client.call("OS_WAIT", 1000)
        assert math.degrees(arm.joint_values()[1]) == pytest.approx(150, abs=0.5)


def test_the_car_steers_with_servo_1():
    with connected_program(arena_scene([(example_robot("Car"), (1000, 1000, 0))])) as (sim, client):
        drive = sim.robots[0].component(AckermannDrive)
        assert client.call("SERVO_SET", 1, 0) == (0,)
        client.call("OS_WAIT", 500)
        left, right = (
            float(sim.world.data.qpos[sim.world.model.jnt_qposadr[sim.world.joint_id(name)]]) for name in drive.knuckles
        )
        # 45 degrees left at the axle's centre: the inner (left) wheel turns more than the outer one
        assert math.degrees(left) > 45 > math.degrees(right) > 30
        assert drive.turning_radius() == pytest.approx(drive.wheelbase, rel=1e-6)  # tan 45 = 1


def test_the_gripper_opens_as_wide_as_its_opening():
    with connected_program(reacher()) as (sim, client):
        gripper = sim.robots[0].component(Gripper)
        assert gripper.opening() == pytest.approx(0.004)  # closed: the fingers 4 mm apart
        client.call("SERVO_SET", 4, 255)
        client.call("OS_WAIT", 1500)
        assert gripper.opening() == pytest.approx(0.004 + 0.090, abs=1e-4)  # Reacher: 90 mm
        client.call("SERVO_SET", 4, 128)
        client.call("OS_WAIT", 1500)
        assert gripper.opening() == pytest.approx(0.004 + 0.090 * 128 / 255, abs=1e-4)


@pytest.mark.parametrize(
    "op,args,message,code",
    [
        ("SERVO_SET", (5, 100), "has no servo 5 (its servos: 1, 2, 3, 4)", g.ERR_BAD_ARGUMENT),
        ("SERVO_SET", (1, 256), "angle 256 is out of range 0..255", g.ERR_BAD_ARGUMENT),
        ("SERVO_SET_RAW", (1, -1), "angle -1 is out of range 0..255", g.ERR_BAD_ARGUMENT),
        ("SERVO_RANGE", (1, 200, 100), "low 200 must be below high 100", g.ERR_BAD_ARGUMENT),
        ("SERVO_RANGE", (1, 0, 300), "high 300 is out of range 0..255", g.ERR_BAD_ARGUMENT),
    ],
)
def test_bad_servo_numbers_and_positions_are_errors(op, args, message, code):
    with connected_program(reacher()) as (sim, client):
        with pytest.raises(RemoteError, match=message.replace("(", r"\(").replace(")", r"\)")) as error:
            client.call(op, *args)
        assert error.value.code == code


def test_a_robot_without_servos_says_so():
    with connected_program(arena_scene([("S4", (1000, 1000, 0))])) as (sim, client):
        with pytest.raises(RemoteError, match="has no servo 1 .its servos: none.") as error:
            client.call("SERVO_SET", 1, 100)
        assert error.value.code == g.ERR_NOT_SUPPORTED
