"""The system group: the robot's name, id and type from the scene; the clock in simulation time."""

from support.connected import connected_program
from support.scenes import arena

from eyesim.protocol import generated as g


def test_machine_name_id_and_type_are_the_robots():
    with connected_program(arena(robots=((500, 500, 0), (1500, 500, 0)))) as (_sim, client):
        assert client.call("OS_MACHINE_NAME") == ("S4",)
        assert client.call("OS_MACHINE_ID") == (1,)
        assert client.call("OS_MACHINE_TYPE") == (1,)  # VEHICLE


def test_the_clock_counts_simulation_milliseconds_at_the_documented_cost():
    with connected_program() as (_sim, client):
        before = client.call("OS_GET_COUNT")[0]
        client.call("OS_WAIT", 1234)
        # OS_GET_COUNT costs 0.1 ms, so the clock reads 1234.1 ms later: 1234 whole milliseconds.
        assert g.OPS_BY_NAME["OS_GET_COUNT"].cost_us == 100
        assert client.call("OS_GET_COUNT")[0] - before == 1234
