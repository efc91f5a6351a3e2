"""One program can neither starve nor sink the others: requests are served in turn, a program's
queue and unread replies are bounded, and a program that stops reading is dropped and forgotten."""

import logging
import socket
import time

import pytest
from support.client import ProgramClient
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.net import program_server
from eyesim.protocol import encode_message, generated as g

ROBOTS = tuple((300 + 200 * i, 500, 90) for i in range(6))


@pytest.fixture
def simulation():
    with running_simulation(arena(robots=ROBOTS)) as (sim, port):
        sim.call_time_us = 0  # answered as soon as served: the order of service is what is tested
        yield sim, port


def _pipeline(client: ProgramClient, name: str, count: int, *args) -> None:
    frames = b"".join(
        encode_message(g.OPS_BY_NAME[name].code, g.KIND_REQUEST, client.next_id + 1 + i, args) for i in range(count)
    )
    client.next_id += count
    client.sock.sendall(frames)


def _wait_until(condition, limit: float = 30.0) -> None:
    deadline = time.monotonic() + limit
    while not condition():
        assert time.monotonic() < deadline
        time.sleep(0.005)


def _session(sim, robot_id: int):
    return next(s for s in sim.sessions if s.robot is not None and s.robot.id == robot_id)


def test_a_pipelining_program_gets_one_turn_per_round_like_the_rest(simulation):
    sim, port = simulation
    greedy, modest = ProgramClient(port), ProgramClient(port)
    greedy.hello("1")
    modest.hello("2")
    greedy.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 1 << 20)
    _pipeline(greedy, "LIDAR_GET", 5000)  # 5000 scans asked for at once
    _wait_until(lambda: _session(sim, 1).queued)  # they are in the simulator's hands
    start = time.perf_counter()
    for _ in range(20):
        assert modest.call("PSD_GET", 1)[0] > 0
    modest_seconds = time.perf_counter() - start
    queued = len(_session(sim, 1).queued)
    assert queued <= program_server.MAX_QUEUED  # the rest waits in the socket, not in memory
    replies = [greedy.receive() for _ in range(5000)]  # all of them come, in order
    assert [m.request_id for m in replies] == list(range(2, 5002))
    assert all(m.kind == g.KIND_REPLY for m in replies)
    # generous guard: behind 5000 queued scans the modest program would wait seconds per call
    assert modest_seconds < 2.0, modest_seconds


def test_handshakes_go_through_while_a_program_floods(simulation):
    sim, port = simulation
    flood = ProgramClient(port)
    flood.hello("1")
    _pipeline(flood, "PSD_GET", 20000, 1)  # never read
    others = [ProgramClient(port) for _ in range(5)]
    assert sorted(client.hello()[1] for client in others) == [2, 3, 4, 5, 6]
    assert all(client.call("OS_GET_COUNT")[0] >= 0 for client in others)


def test_a_program_that_stops_reading_is_held_back_then_dropped_and_its_memory_returned(
    simulation, caplog, monkeypatch
):
    sim, port = simulation
    monkeypatch.setattr(program_server, "STALL_TIMEOUT", 1.0)
    reader, sleeper = ProgramClient(port), ProgramClient(port)
    reader.hello("1")
    sleeper.hello("2")
    sleeper.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    with caplog.at_level(logging.WARNING, logger="eyesim.net"):
        _pipeline(sleeper, "LIDAR_GET", 20000)  # 29 MB of scans asked for, never read
        deadline = time.monotonic() + 20
        while any(s.robot is not None and s.robot.id == 2 for s in sim.sessions):
            assert reader.call("PSD_GET", 1)[0] > 0  # served all along
            held = sum(len(c.backlog) for c in sim.network.connections)
            # reading stops at the pause limit; what was queued by then is still answered
            assert held <= program_server.READ_PAUSE_BACKLOG + program_server.MAX_QUEUED * 1500
            assert time.monotonic() < deadline, "the sleeping program was never dropped"
            time.sleep(0.05)
    assert "has not read its replies" in caplog.text
    assert all(not c.backlog for c in sim.network.connections)
    assert reader.call("PSD_GET", 1)[0] > 0


def test_large_replies_piling_up_beyond_the_limit_close_the_connection(simulation, caplog):
    sim, port = simulation
    reader, sleeper = ProgramClient(port), ProgramClient(port)
    reader.hello("1")
    sleeper.hello("2")
    sleeper.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    sleeper.call("CAM_INIT", 3)  # CAM1MP: 2.8 MB an image
    with caplog.at_level(logging.WARNING, logger="eyesim.net"):
        _pipeline(sleeper, "CAM_GET", 20)  # 57 MB of images, never read
        deadline = time.monotonic() + 60
        while any(s.robot is not None and s.robot.id == 2 for s in sim.sessions):
            assert time.monotonic() < deadline
            held = sum(len(c.backlog) for c in sim.network.connections)
            assert held <= program_server.MAX_BACKLOG
            time.sleep(0.05)
    assert "replies unread; closing the connection" in caplog.text
    assert all(not c.backlog for c in sim.network.connections)
    assert reader.call("PSD_GET", 1)[0] > 0


def test_with_a_call_time_a_pipelining_program_is_served_one_call_time_at_a_time(simulation):
    """Its requests are carried out one call time apart, as one program calling in a loop would be:
    not all at once with their replies parked (that would let it take any amount of work and memory)."""
    sim, port = simulation
    sim.call_time_us = 20_000  # 20 ms a call
    greedy, modest = ProgramClient(port), ProgramClient(port)
    greedy.hello("1")
    modest.hello("2")
    start_us = sim.time_us
    _pipeline(greedy, "LIDAR_GET", 200)
    _wait_until(lambda: sim.time_us - start_us >= 300_000)  # 15 call times
    held = len(sim.timing.held)
    greedy.sock.settimeout(0.02)
    replies = 0
    try:
        while True:  # what has come so far (a new reply comes every 20 ms: stop at the first gap)
            greedy.receive()
            replies += 1
    except OSError:
        pass
    elapsed_ms = (sim.time_us - start_us) / 1000
    assert held <= 2  # its current call (no heap of parked replies)
    assert 5 <= replies <= elapsed_ms / 20 + 2, (replies, elapsed_ms)
    assert modest.call("PSD_GET", 1)[0] > 0
