"""A program whose blocking calls fill its cap of held requests (MAX_QUEUED) is not read any more.
If it then closes its connection, that is noticed all the same, and its robot and descriptor are
freed; one that sends still more calls is closed with a clear error (the calls behind the waiting
ones would hide its close: a program that flooded and left kept its robot for the rest of the run)."""

import threading

import pytest

from support.client import ProgramClient, RemoteError
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.net.program_server import MAX_QUEUED
from eyesim.protocol import decode_payload, encode_frame, encode_payload, generated as g

FOREVER = 0xFFFF  # KEYWait's timeout that never ends


def until(condition, what: str) -> None:
    for _ in range(1200):
        if condition():
            return
        threading.Event().wait(0.05)
    raise AssertionError(f"never: {what}")


def robot_taken(port: int) -> bool:
    client = ProgramClient(port)
    try:
        client.hello("1")
        return False
    except RemoteError as error:
        assert error.code == g.ERR_NO_ROBOT, error
        return True
    finally:
        client.close()


def key_waits(count: int) -> bytes:
    return (
        encode_frame(g.OP_KEY_WAIT, g.KIND_REQUEST, 7, encode_payload(g.OPS[g.OP_KEY_WAIT].request, (FOREVER,))) * count
    )


def test_a_program_whose_waiting_calls_fill_its_cap_and_that_left_frees_its_robot():
    with running_simulation(arena(robots=((500, 500, 0),))) as (sim, port):
        flooder = ProgramClient(port)
        flooder.hello("1")
        flooder.sock.sendall(key_waits(MAX_QUEUED))
        until(
            lambda: any(c.held() == MAX_QUEUED and not c.reading() for c in list(sim.network.connections)),
            "the simulator holds the cap's worth of calls and stops reading",
        )
        assert robot_taken(port)
        flooder.close()
        until(lambda: not robot_taken(port), "the robot is free again")
        until(lambda: len(sim.network.connections) == 0, "the connection is closed")


def test_a_program_that_sends_more_calls_while_its_cap_waits_is_closed_with_an_error():
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180)))) as (sim, port):
        flooder, honest = ProgramClient(port), ProgramClient(port)
        flooder.hello("1")
        honest.hello("2")
        flooder.sock.sendall(key_waits(4 * MAX_QUEUED))
        refusal = flooder.receive()
        assert refusal.kind == g.KIND_ERROR
        code, text = decode_payload(g.ERROR_PAYLOAD, refusal.payload)
        assert code == g.ERR_NOT_SUPPORTED and f"more than {MAX_QUEUED} calls waiting at once" in text
        with pytest.raises(ConnectionError):
            flooder.receive()
        until(lambda: not robot_taken(port), "robot 1 is free again")
        assert honest.call("PSD_GET", 1)[0] > 0
