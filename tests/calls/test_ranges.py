"""Values are checked at the edge (protocol.json's ranges) and a reply can never take the simulation
down: the int32 limits that once made the reply encoder raise on the simulation thread, a handler
that fails, a result that does not fit its field. Each gets an error reply; everyone goes on."""

import pytest
from support.client import ProgramClient, RemoteError
from support.connected import connected_program
from support.worlds import arena_scene

from eyesim import calls
from eyesim.protocol import generated as g

INT_MAX, INT_MIN = 2**31 - 1, -(2**31)


def _scene():
    return arena_scene([("S4", (500, 500, 0)), ("S4", (1500, 1500, 0))], objects=[("Can", (1000, 1500, 0))])


@pytest.mark.parametrize(
    "op,args,field",
    [
        ("VW_SET_POSITION", (INT_MAX, 0, 0), "x"),
        ("VW_SET_POSITION", (0, INT_MIN, 0), "y"),
        ("VW_SET_POSITION", (0, 0, INT_MAX), "phi"),
        ("VW_STRAIGHT", (INT_MAX, 300), "dist"),
        ("VW_STRAIGHT", (100, INT_MIN), "lin_speed"),
        ("VW_TURN", (INT_MIN, 90), "angle"),
        ("VW_CURVE", (INT_MAX, 90, 100), "dist"),
        ("VW_DRIVE", (INT_MAX, 0, 100), "dx"),
        ("VW_SET_SPEED", (INT_MAX, 0), "lin_speed"),
        ("SIM_SET_ROBOT", (0, INT_MAX, 500, 0, 0), "x"),
        ("SIM_SET_OBJECT", (1, 500, 500, INT_MIN, 0), "z"),
        ("MOTOR_SPEED", (1, INT_MAX), "ticks"),
    ],
)
def test_values_beyond_the_documented_range_are_refused_before_any_work(op, args, field):
    with connected_program(_scene()) as (sim, client):
        before = client.call("VW_GET_POSITION")
        with pytest.raises(RemoteError) as error:
            client.call(op, *args)
        assert error.value.code == g.ERR_BAD_ARGUMENT
        assert error.value.message.startswith(f"{field} = ") and "is outside" in error.value.message
        assert client.call("VW_GET_POSITION") == before
        assert client.call("VW_REMAIN") == (0,)


def test_the_largest_legal_values_answer_within_the_reply_fields():
    with connected_program(_scene()) as (sim, client):
        client.call("VW_SET_POSITION", 10_000_000, -10_000_000, 3_600_000)
        assert client.call("VW_GET_POSITION") == (0, 10_000_000, -10_000_000, 0)
        client.call("VW_STRAIGHT", 10_000_000, 100_000)
        assert client.call("VW_REMAIN") == (10_000_000,)
        client.call("VW_DRIVE", 10_000_000, -10_000_000, 100_000)
        assert 0 < client.call("VW_REMAIN")[0] < 2**31


def test_a_handler_that_raises_answers_its_caller_and_the_simulation_goes_on(monkeypatch, caplog):
    def broken(sim, robot, request):
        raise ZeroDivisionError("a bug in a handler")

    monkeypatch.setitem(calls.HANDLERS, g.OP_PSD_GET, broken)
    with connected_program(_scene(), mode="realtime") as (sim, client):  # realtime: `other` may idle
        other = ProgramClient(client.sock.getpeername()[1])
        other.hello("2")
        with pytest.raises(RemoteError, match="internal simulator error"):
            client.call("PSD_GET", 1)
        time_before = client.call("OS_GET_COUNT")[0]
        client.call("OS_WAIT", 100)
        assert client.call("OS_GET_COUNT")[0] >= time_before + 100  # time goes on
        assert other.call("VW_GET_POSITION")[0] == 0
    assert "a bug in a handler" in caplog.text and "PSD_GET" in caplog.text


def test_a_result_that_does_not_fit_its_reply_is_an_error_not_a_crash(monkeypatch, caplog):
    monkeypatch.setitem(calls.HANDLERS, g.OP_VW_REMAIN, lambda sim, robot, request: (2**40,))
    with connected_program(_scene()) as (sim, client):
        with pytest.raises(RemoteError, match="does not fit the reply"):
            client.call("VW_REMAIN")
        assert client.call("PSD_GET", 1)[0] > 0
    assert "does not encode" in caplog.text
