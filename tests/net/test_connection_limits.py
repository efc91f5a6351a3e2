"""What a crowd of idle sockets can make the simulator hold: at most MAX_CONNECTIONS connections,
none for longer than the handshake timeout without a HELLO, and no busy loop when the process runs
out of descriptors. A real program still gets in."""

from __future__ import annotations

import logging
import os
import resource
import socket
import time

from support.client import ProgramClient
from support.scenes import arena
from support.simulator import running_simulation



def wait_until(condition, timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, "condition not met in time"
        time.sleep(0.02)


def closed_by_peer(sock: socket.socket) -> bool:
    sock.setblocking(False)
    try:
        return sock.recv(1) == b""
    except BlockingIOError:
        return False
    except OSError:
        return True


def test_connections_past_the_cap_are_refused_and_logged(caplog):
    caplog.set_level(logging.WARNING, logger="eyesim.net")
    with running_simulation(arena()) as (sim, port):
        sim.network.max_connections = 20
        sim.network.handshake_timeout = 60.0
        idle = [socket.create_connection(("127.0.0.1", port)) for _ in range(30)]
        wait_until(lambda: len(sim.network.connections) == 20)
        wait_until(lambda: sum(closed_by_peer(s) for s in idle) == 10)
        assert any("refused a program connection" in r.message for r in caplog.records)
        for sock in idle:
            sock.close()
        wait_until(lambda: not sim.network.connections)
        assert ProgramClient(port).hello()[1] == 1  # room again


def test_a_connection_without_a_handshake_is_closed(caplog):
    caplog.set_level(logging.WARNING, logger="eyesim.net")
    with running_simulation(arena()) as (sim, port):
        sim.network.handshake_timeout = 0.5
        idle = socket.create_connection(("127.0.0.1", port))
        program = ProgramClient(port)
        assert program.hello()[1] == 1
        wait_until(lambda: closed_by_peer(idle))
        assert any("sent no handshake within 0.5 s" in r.message for r in caplog.records)
        assert program.call("PSD_GET", 1)[0] > 0  # the program that said HELLO stays


def test_running_out_of_descriptors_rests_instead_of_spinning(caplog):
    """With the descriptor limit reached, the listener would be readable for ever: accepting rests."""
    caplog.set_level(logging.WARNING, logger="eyesim.net")
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    with running_simulation(arena()) as (sim, port):
        sim.network.handshake_timeout = 60.0
        held = []
        resource.setrlimit(resource.RLIMIT_NOFILE, (len(os.listdir("/proc/self/fd")) + 40, hard))
        try:
            try:
                while len(held) < 200:
                    held.append(socket.create_connection(("127.0.0.1", port), timeout=2))
            except OSError:
                pass  # our own side ran out first
            wait_until(lambda: any("out of file descriptors" in r.message for r in caplog.records))
            steps = sim.steps
            wait_until(lambda: sim.steps > steps + 100)  # the simulation goes on meanwhile
        finally:
            for sock in held:
                sock.close()
            resource.setrlimit(resource.RLIMIT_NOFILE, (soft, hard))
        wait_until(lambda: not sim.network.connections)
        assert ProgramClient(port).hello()[1] == 1
