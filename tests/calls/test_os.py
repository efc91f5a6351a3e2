"""The system group: the robot's name, id and type from the scene; the clock in simulation time."""

import pytest
from support.client import RemoteError
from support.connected import connected_program
from support.scenes import arena

from eyesim.core.engine import DEFAULT_CALL_TIME_US
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
        # Reading the clock is local (a few us, not the call time), the wait exactly its 1234 ms.
        clock = g.OPS_BY_NAME["OS_GET_COUNT"]
        assert clock.cost == "local" and sim.call_cost_us(clock) == clock.cost_us < DEFAULT_CALL_TIME_US
        assert client.call("OS_GET_COUNT")[0] - before == 1234


def test_sleep_waits_seconds_and_nanoseconds_of_simulation_time():
    with connected_program() as (sim, client):
        # 999_999.001 us are rounded up to a whole second: a started microsecond counts, so that
        # even a 1 ns sleep lets time go on (and the clock stays on whole ms here).
        for seconds, nanoseconds, waited_ms in ((0, 500_000_000, 500), (2, 0, 2000), (0, 999_999_001, 1000), (0, 0, 0)):
            before = client.call("OS_GET_COUNT")[0]
            assert client.call("OS_SLEEP", seconds, nanoseconds) == (0,)
            # the clock never shows the same millisecond twice in a row (deterministic mode)
            assert client.call("OS_GET_COUNT")[0] - before == max(waited_ms, 1)
        with pytest.raises(RemoteError, match="sleep: 1000000000 nanoseconds is not below one second"):
            client.call("OS_SLEEP", 0, 1_000_000_000)
