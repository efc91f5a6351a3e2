"""Blocking calls count in a program's cap of requests the simulator holds (MAX_QUEUED): 5,000
pipelined KEYWait requests used to be taken in full, costing 99 % CPU and others' p99 2.9 s."""

from __future__ import annotations

import threading
import time

from support.client import ProgramClient
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.net.program_server import MAX_QUEUED
from eyesim.protocol import encode_message, generated as g


def test_a_flood_of_blocking_calls_is_held_back_and_others_go_on():
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180)))) as (sim, port):
        flooder = ProgramClient(port)
        flooder.hello("1")
        flood = b"".join(encode_message(g.OP_KEY_WAIT, g.KIND_REQUEST, 1000 + k, (0xFFFF,)) for k in range(5000))
        sender = threading.Thread(target=flooder.sock.sendall, args=(flood,), daemon=True)
        sender.start()
        honest = ProgramClient(port)
        honest.hello("2")
        for _ in range(50):
            assert honest.call("PSD_GET", 1)[0] > 0

        held = []
        sim.call(
            lambda s: held.append(
                max((len(x.pending) + len(x.queued), len(x.pending), len(x.queued)) for x in s.sessions)
            )
        )
        deadline = time.monotonic() + 10
        while not held:
            assert time.monotonic() < deadline
            time.sleep(0.01)
        assert held[0][0] <= MAX_QUEUED, held  # the rest waits in the sockets' buffers, unread
        flooder.close()
