"""Warnings a client can cause by the thousand are summed up: the first of each reason in full, the
rest counted, and one line a period says how many (a soak's flooder once wrote 93,579 lines)."""

from __future__ import annotations

import logging
import socket
import threading
import time

from support.client import ProgramClient
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.net.program_server import MAX_QUEUED
from eyesim.net.repeated_warnings import RepeatedWarnings
from eyesim.protocol import encode_message, generated as g


def wait_until(condition, timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, "condition not met in time"
        time.sleep(0.02)


def messages(caplog, text: str) -> list[str]:
    return [r.getMessage() for r in caplog.records if text in r.getMessage()]


def test_the_first_of_each_reason_is_logged_and_the_rest_counted(caplog):
    log = logging.getLogger("eyesim.test.repeated")
    warnings = RepeatedWarnings(log, period=1.0)
    with caplog.at_level(logging.WARNING, logger="eyesim.test.repeated"):
        for k in range(1000):
            warnings.warn("closed: a malformed frame", "peer %d: bad frame", k)
        for k in range(10):
            warnings.warn("closed: no handshake", "peer %d: silent", k)
        warnings.summarize(time.monotonic())  # within the period: nothing yet
        assert [r.getMessage() for r in caplog.records] == ["peer 0: bad frame", "peer 0: silent"]
        warnings.summarize(time.monotonic() + 1.0)
        lines = [r.getMessage() for r in caplog.records][2:]
        assert lines == [
            "closed: a malformed frame: 999 more program connection(s) in the last 1 s",
            "closed: no handshake: 9 more program connection(s) in the last 1 s",
        ]
        warnings.warn("closed: a malformed frame", "peer %d: bad frame", 1000)  # a new period: in full
        warnings.summarize(time.monotonic() + 5.0)  # nothing counted: no summary
    assert [r.getMessage() for r in caplog.records][4:] == ["peer 1000: bad frame"]


def test_connections_refused_past_the_cap_give_one_line_and_a_count(caplog):
    caplog.set_level(logging.WARNING, logger="eyesim.net")
    with running_simulation(arena()) as (sim, port):
        sim.network.max_connections = 1
        sim.network.warnings.period = 3600.0  # no summary until the test asks for one
        program = ProgramClient(port)
        assert program.hello()[1] == 1
        refused = [socket.create_connection(("127.0.0.1", port)) for _ in range(200)]
        for sock in refused:
            sock.settimeout(10)
            assert sock.recv(1) == b""  # closed at once by the simulator
            sock.close()
        assert len(messages(caplog, "refused a program connection")) == 1
        assert not messages(caplog, "more program connection(s)")
        sim.network.warnings.period = 0.0
        wait_until(lambda: messages(caplog, "more program connection(s)"))
        (summary,) = messages(caplog, "more program connection(s)")
        assert summary.startswith("refused: at the cap of 1 connections: 199 more program connection(s) in the last ")
        assert program.call("PSD_GET", 1)[0] > 0  # the program inside was served all along


def test_flooders_closed_over_the_cap_of_waiting_calls_give_one_line_and_a_count(caplog):
    caplog.set_level(logging.WARNING, logger="eyesim.net")
    robots = tuple((300 + 200 * k, 500, 0) for k in range(8))
    with running_simulation(arena(robots=robots)) as (sim, port):
        sim.network.warnings.period = 3600.0
        flood = b"".join(
            encode_message(g.OP_KEY_WAIT, g.KIND_REQUEST, 100 + k, (0xFFFF,)) for k in range(MAX_QUEUED + 10)
        )

        def flooder(robot: int) -> None:
            client = ProgramClient(port)
            client.hello(str(robot))
            client.sock.sendall(flood)
            client.sock.settimeout(10)
            while client.sock.recv(65536):  # the error reply, then the close
                pass
            client.close()

        threads = [threading.Thread(target=flooder, args=(robot,)) for robot in range(1, 9)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join(30)
        closed = f"more than {MAX_QUEUED} calls waiting at once"
        wait_until(lambda: len(sim.sessions) == 0)
        assert len(messages(caplog, closed)) == 1
        sim.network.warnings.period = 0.0
        wait_until(lambda: messages(caplog, "more program connection(s)"))
        (summary,) = messages(caplog, "more program connection(s)")
        assert summary.startswith(f"closed: {closed}: 7 more program connection(s) in the last ")
