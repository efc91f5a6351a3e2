"""The V-omega group on the robots it serves and the ones it does not."""

import pytest
from support.client import RemoteError
from support.connected import connected_program
from support.worlds import arena_scene, example_robot

from eyesim.protocol import generated as g


def test_remain_and_stalled_while_driving():
    with connected_program(arena_scene([("S4", (500, 500, 0))], size=1000)) as (sim, client):
        assert client.call("VW_REMAIN") == (0,)
        client.call("VW_STRAIGHT", 800, 300)
        assert client.call("VW_REMAIN") == (800,)
        client.call("OS_WAIT", 500)
        assert 500 < client.call("VW_REMAIN")[0] < 800
        assert client.call("VW_STALLED") == (0,)
        client.call("OS_WAIT", 3000)  # the wall is 400 mm ahead
        assert client.call("VW_STALLED") == (3,)
        assert client.call("VW_DONE") == (1,)  # a stalled manoeuvre ends, and still says why
        client.call("OS_WAIT", 300)
        assert client.call("VW_STALLED") == (3,)
        client.call("VW_SET_SPEED", 0, 0)
        client.call("OS_WAIT", 300)
        assert client.call("VW_STALLED") == (0,)
        client.call("VW_TURN", 90, 90)
        assert client.call("VW_REMAIN") == (round(3.14159265 / 2 * 45),)  # each wheel's travel on the spot
        client.call("VW_WAIT")
        assert client.call("VW_REMAIN") == (0,)


@pytest.mark.parametrize("turn,stalled", [(-60, 1), (60, 2)])
def test_one_stalled_wheel_sets_its_bit(turn, stalled):
    # Nose at the north wall, turning on the spot: the wheel that drives the nose into the wall is
    # blocked, the other one turns on (the robot pivots back about its corner).
    with connected_program(arena_scene([("S4", (500, 910, 90))], size=1000)) as (sim, client):
        client.call("VW_SET_SPEED", 0, turn)
        client.call("OS_WAIT", 300)
        assert client.call("VW_STALLED") == (stalled,)


@pytest.mark.parametrize("robot", ["Minnow", "Reacher"])
def test_robots_without_a_wheeled_drive_have_no_vw(robot):
    with connected_program(arena_scene([(example_robot(robot), (1500, 1500, 0))], wall_height=1500)) as (sim, client):
        for op, args in (
            ("VW_SET_SPEED", (100, 0)),
            ("VW_STRAIGHT", (100, 100)),
            ("VW_REMAIN", ()),
            ("VW_STALLED", ()),
            ("VW_CURVE", (100, 10, 100)),
            ("VW_DRIVE", (100, 10, 100)),
        ):
            with pytest.raises(RemoteError, match="has no V-omega drive") as error:
                client.call(op, *args)
            assert error.value.code == g.ERR_NOT_SUPPORTED


def test_the_car_refuses_turns_on_the_spot_and_arcs_tighter_than_its_steering():
    with connected_program(arena_scene([(example_robot("Car"), (1500, 1500, 0))])) as (sim, client):
        for op, args in (("VW_TURN", (90, 60)), ("VW_SET_SPEED", (0, 30)), ("VW_CURVE", (0, 90, 100))):
            with pytest.raises(RemoteError, match="the Ackermann car cannot turn on the spot"):
                client.call(op, *args)
        # VWDrive(100, 100) is a quarter circle of 100 mm; the car's smallest is 160 mm.
        with pytest.raises(RemoteError, match="an arc of radius 100 mm is tighter than the Ackermann car can drive"):
            client.call("VW_DRIVE", 100, 100, 100)
        assert client.call("VW_DONE") == (1,)
        # Driving on, a turn rate beyond the tightest arc is limited to it: 100 mm/s on 160 mm.
        client.call("VW_SET_SPEED", 100, 90)
        client.call("OS_WAIT", 1000)
        _, v, w = client.call("VW_GET_SPEED")
        assert v == pytest.approx(100, abs=3) and w == pytest.approx(36, abs=2)  # 100 / 160 rad/s


def test_a_motor_command_takes_the_mecanum_wheels_from_vw():
    with connected_program(arena_scene([(example_robot("Mecanum"), (1500, 1500, 0))])) as (sim, client):
        client.call("VW_STRAIGHT", 500, 200)
        client.call("OS_WAIT", 300)
        client.call("MOTOR_DRIVE", 3, 0)
        assert client.call("VW_DONE") == (1,)
