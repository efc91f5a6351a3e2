"""The system group: the robot's name, id and type from the scene; the clock in simulation time."""

from support.connected import connected_program
from support.scenes import arena

from eyesim.engine import DEFAULT_CALL_TIME_US
from eyesim.protocol import generated as g


def test_machine_name_id_and_type_are_the_robots():
    with connected_program(arena(robots=((500, 500, 0), (1500, 500, 0)))) as (_sim, client):
        assert client.call("OS_MACHINE_NAME") == ("S4",)
        assert client.call("OS_MACHINE_ID") == (1,)
        assert client.call("OS_MACHINE_TYPE") == (1,)  # VEHICLE


def test_the_clock_counts_simulation_milliseconds_at_the_documented_cost():
    with connected_program() as (sim, client):
        before = client.call("OS_GET_COUNT")[0]
        client.call("OS_WAIT", 1234)
        # OS_GET_COUNT costs the call time (whole ms by default), the wait exactly its 1234 ms.
        call_ms = sim.call_cost_us(g.OPS_BY_NAME["OS_GET_COUNT"]) / 1000
        assert call_ms == DEFAULT_CALL_TIME_US / 1000 >= 1
        assert client.call("OS_GET_COUNT")[0] - before == call_ms + 1234
