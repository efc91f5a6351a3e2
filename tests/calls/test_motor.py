"""The motor group: motor and encoder numbers per drive type, ranges, and what a type cannot do."""

import math

import pytest
from support.client import RemoteError
from support.connected import connected_program
from support.worlds import arena_scene, example_robot

from eyesim.protocol import generated as g
from eyesim.robot.components.vw import VwController


def test_motor_drive_turns_a_wheel_and_its_encoder_counts_it():
    with connected_program(arena_scene([("S4", (1000, 1000, 0))])) as (sim, client):
        assert client.call("MOTOR_DRIVE", 1, 10) == (0,)  # 10 % of 11000 ticks/s
        client.call("OS_WAIT", 500)
        left, right = client.call("ENCODER_READ", 1)[0], client.call("ENCODER_READ", 2)[0]
        assert 450 < left < 560 and abs(right) < 20  # only the left wheel drives: the robot turns right
        assert -70 < sim.robots[0].pose_mm()[3] < -40  # 85 mm/s about the right wheel, 90 mm away
        assert client.call("ENCODER_RESET", 1) == (0,)
        assert abs(client.call("ENCODER_READ", 1)[0]) < 50  # counting on from 0 (it still rolls)


def test_direct_motor_commands_take_the_wheels_over_from_vw():
    with connected_program(arena_scene([("S4", (1000, 1000, 0))])) as (sim, client):
        client.call("VW_SET_SPEED", 200, 0)
        client.call("OS_WAIT", 500)
        client.call("MOTOR_DRIVE", 1, 0)
        client.call("MOTOR_DRIVE", 2, 0)
        client.call("OS_WAIT", 2500)  # unpowered DC motors brake the robot to a stop
        x = sim.robots[0].pose_mm()[0]
        client.call("OS_WAIT", 500)
        assert sim.robots[0].pose_mm()[0] == pytest.approx(x, abs=1)  # stopped: VW no longer drives
        assert sim.robots[0].component(VwController).done


def test_pid_speed_control_and_back_to_open_loop():
    with connected_program(arena_scene([("S4", (1000, 1000, 0))])) as (sim, client):
        assert client.call("MOTOR_PID", 1, 100, 60, 10) == (0,)
        assert client.call("MOTOR_SPEED", 1, 2200) == (0,)  # two turns a second
        client.call("OS_WAIT", 1000)
        start = client.call("ENCODER_READ", 1)[0]
        client.call("OS_WAIT", 1000)
        assert client.call("ENCODER_READ", 1)[0] - start == pytest.approx(2200, rel=0.02)
        assert client.call("MOTOR_PID_OFF", 1) == (0,)
        client.call("OS_WAIT", 2500)
        start = client.call("ENCODER_READ", 1)[0]
        client.call("OS_WAIT", 500)
        assert abs(client.call("ENCODER_READ", 1)[0] - start) < 20  # unpowered: it ran down
        assert client.call("MOTOR_DRIVE_RAW", 2, -30) == (0,)
        client.call("OS_WAIT", 500)
        assert client.call("ENCODER_READ", 2)[0] < -300


@pytest.mark.parametrize(
    "op,args,message",
    [
        ("MOTOR_DRIVE", (3, 50), "has no motor 3 (its motors: 1, 2)"),
        ("MOTOR_DRIVE", (0, 50), "has no motor 0"),
        ("MOTOR_DRIVE", (1, 101), "speed 101 is out of range -100..100"),
        ("MOTOR_DRIVE_RAW", (2, -150), "speed -150 is out of range"),
        ("MOTOR_PID", (1, 256, 0, 0), "p 256 is out of range 0..255"),
        ("MOTOR_PID", (1, 10, -1, 0), "i -1 is out of range"),
        ("MOTOR_SPEED", (1, 20000), "speed 20000 ticks/s is out of range -11000..11000"),
        ("MOTOR_PID_OFF", (9,), "has no motor 9"),
        ("ENCODER_READ", (3,), "has no encoder 3 (its encoders: 1, 2)"),
        ("ENCODER_RESET", (-1,), "has no encoder -1"),
    ],
)
def test_bad_numbers_and_values_are_errors(op, args, message):
    with connected_program(arena_scene([("S4", (1000, 1000, 0))])) as (sim, client):
        with pytest.raises(RemoteError, match=message.replace("(", r"\(").replace(")", r"\)")) as error:
            client.call(op, *args)
        assert error.value.code == g.ERR_BAD_ARGUMENT
        assert client.call("OS_GET_COUNT")[0] >= 0  # and the connection goes on


def test_what_a_robot_type_cannot_do_is_not_supported():
    scene = arena_scene(
        [(example_robot("Minnow"), (1500, 1500, 0)), (example_robot("Reacher"), (500, 500, 0))], wall_height=1500
    )
    with connected_program(scene) as (sim, client):
        for op, args in (("MOTOR_SPEED", (1, 100)), ("MOTOR_PID", (1, 1, 1, 1)), ("MOTOR_PID_OFF", (2,))):
            with pytest.raises(RemoteError, match="is a thruster without an encoder") as error:
                client.call(op, *args)
            assert error.value.code == g.ERR_NOT_SUPPORTED
        with pytest.raises(RemoteError, match="has no encoder 1 .its encoders: none.") as error:
            client.call("ENCODER_READ", 1)
        assert error.value.code == g.ERR_NOT_SUPPORTED
        assert client.call("MOTOR_DRIVE", 4, -100) == (0,)  # thrusters do drive
    with connected_program(scene) as (sim, client):
        client.close()
    from support.client import ProgramClient
    from support.simulator import running_simulation

    with running_simulation(scene, "deterministic") as (sim, port):
        arm = ProgramClient(port)
        arm.hello("2")
        with pytest.raises(RemoteError, match="has no motor 1 .its motors: none.") as error:
            arm.call("MOTOR_DRIVE", 1, 10)
        assert error.value.code == g.ERR_NOT_SUPPORTED
        arm.close()


def test_omni_and_ackermann_number_their_motors():
    scene = arena_scene([(example_robot("Mecanum"), (1000, 1000, 0)), (example_robot("Car"), (2000, 1000, 0))])
    with connected_program(scene) as (sim, client):
        for motor in (1, 2, 3, 4):
            assert client.call("MOTOR_SPEED", motor, 360) == (0,)  # half a turn a second, all ahead
        client.call("OS_WAIT", 2000)
        assert sim.robots[0].pose_mm()[0] > 1000 + 0.9 * 1.5 * math.pi * 60 / 2
        assert [client.call("ENCODER_READ", m)[0] > 600 for m in (1, 2, 3, 4)] == [True] * 4
        with pytest.raises(RemoteError, match="has no motor 5"):
            client.call("MOTOR_DRIVE", 5, 10)
