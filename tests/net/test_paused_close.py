"""A program that pipelines more blocking calls than the cap takes and then closes its connection
is noticed as gone, though its socket is no longer read (the end of its stream waits behind the
requests the simulator has not taken): its robot and descriptor are freed. Before, both stayed
taken for as long as the simulator ran."""

import threading

from support.client import ProgramClient, RemoteError
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.net.program_server import MAX_QUEUED
from eyesim.protocol import encode_frame, encode_payload, generated as g

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


def test_a_program_that_pipelined_blocking_calls_and_left_frees_its_robot():
    with running_simulation(arena(robots=((500, 500, 0),))) as (sim, port):
        flooder = ProgramClient(port)
        flooder.hello("1")
        key_wait = encode_frame(g.OP_KEY_WAIT, g.KIND_REQUEST, 7, encode_payload(g.OPS[g.OP_KEY_WAIT].request, (FOREVER,)))
        flooder.sock.sendall(key_wait * (4 * MAX_QUEUED))
        until(lambda: any(c.held() == MAX_QUEUED and not c.reading() for c in list(sim.network.connections)),
              "the simulator holds the cap's worth of calls and stops reading")
        assert robot_taken(port)
        flooder.close()
        until(lambda: not robot_taken(port), "the robot is free again")
        until(lambda: len(sim.network.connections) == 0, "the connection is closed")
