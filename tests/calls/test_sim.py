"""The simulation group: true poses of robots and objects by id, counts, and what cannot move."""

import pytest
from support.client import RemoteError
from support.connected import connected_program
from support.worlds import arena_scene, example_robot


def scene():
    return arena_scene(
        [("S4", (500, 500, 0)), (example_robot("Reacher"), (1500, 1500, 0)), ("S4", (500, 1500, 90))],
        objects=[("Can", (1000, 500, 0)), ("Crate1", (2000, 2000, 0)), ("Soccer", (1000, 1000, 0))],
    )


def test_ids_counts_and_poses():
    with connected_program(scene()) as (sim, client):
        assert client.call("SIM_GET_ROBOT_COUNT") == (3,)
        assert client.call("SIM_GET_OBJECT_COUNT") == (3,)
        assert client.call("SIM_GET_ROBOT", 0) == client.call("SIM_GET_ROBOT", 1)  # 0 = the caller
        assert client.call("SIM_GET_ROBOT", 3) == (0, 500, 1500, 0, 90)
        assert client.call("SIM_GET_OBJECT", 1) == (0, 1000, 500, 0, 0)
        assert client.call("SIM_GET_OBJECT", 3) == (0, 1000, 1000, 0, 0)


def test_objects_and_robots_can_be_moved_but_fixed_ones_cannot():
    with connected_program(scene()) as (sim, client):
        assert client.call("SIM_SET_OBJECT", 1, 1200, 700, 0, 45) == (0,)
        client.call("OS_WAIT", 200)
        assert client.call("SIM_GET_OBJECT", 1) == (0, 1200, 700, 0, 45)
        assert client.call("SIM_SET_OBJECT", 3, 1000, 1000, 300, 0) == (0,)  # dropped from 300 mm
        client.call("OS_WAIT", 20)
        assert 200 < client.call("SIM_GET_OBJECT", 3)[3] < 300
        with pytest.raises(RemoteError, match="object 2 .Crate1. is fixed and cannot be moved"):
            client.call("SIM_SET_OBJECT", 2, 100, 100, 0, 0)
        with pytest.raises(RemoteError, match="robot 2 .Reacher. is mounted on the floor"):
            client.call("SIM_SET_ROBOT", 2, 100, 100, 0, 0)
        assert client.call("SIM_SET_ROBOT", 3, 800, 1600, 0, 180) == (0,)
        assert client.call("SIM_GET_ROBOT", 3) == (0, 800, 1600, 0, 180)


@pytest.mark.parametrize(
    "op,args,message",
    [
        ("SIM_GET_ROBOT", (4,), "no robot 4 .0 = this robot, 1..3 = the scene's."),
        ("SIM_SET_ROBOT", (-1, 0, 0, 0, 0), "no robot -1"),
        ("SIM_GET_OBJECT", (0,), "no object 0 .1..3."),
        ("SIM_SET_OBJECT", (4, 0, 0, 0, 0), "no object 4"),
    ],
)
def test_unknown_ids_are_errors(op, args, message):
    with connected_program(scene()) as (sim, client):
        with pytest.raises(RemoteError, match=message):
            client.call(op, *args)


def test_a_scene_without_objects_says_so():
    with connected_program(arena_scene([("S4", (500, 500, 0))])) as (sim, client):
        assert client.call("SIM_GET_OBJECT_COUNT") == (0,)
        with pytest.raises(RemoteError, match="no object 1 .the scene has none."):
            client.call("SIM_GET_OBJECT", 1)


@pytest.mark.parametrize("z", [-10_000_000, -50])
def test_a_place_below_the_floor_is_on_the_floor(z):
    """A robot or object set 10 km below the floor used to be flung out (z = 309 km a second later)."""
    with connected_program(scene()) as (sim, client):
        assert client.call("SIM_SET_ROBOT", 0, 800, 800, z, 0) == (0,)
        assert client.call("SIM_SET_OBJECT", 1, 1200, 700, z, 0) == (0,)
        client.call("OS_WAIT", 1000)
        robot, can = client.call("SIM_GET_ROBOT", 0), client.call("SIM_GET_OBJECT", 1)
        assert robot[1:3] == (800, 800) and 0 <= robot[3] <= 5
        assert can[1:3] == (1200, 700) and 0 <= can[3] <= 5
