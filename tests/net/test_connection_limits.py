"""What a crowd of idle sockets can make the simulator hold: at most MAX_CONNECTIONS connections,
none for longer than the handshake timeout without a HELLO, and no busy loop when the process runs
out of descriptors. A real program still gets in."""

from __future__ import annotations

import logging
import re
import resource
import socket
import subprocess
import time

from support.client import ProgramClient, RemoteError
from support.programs import eyesim_command
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


def test_silent_sockets_cannot_keep_programs_out_of_the_capped_run(caplog):
    caplog.set_level(logging.WARNING, logger="eyesim.net")
    with running_simulation(arena()) as (sim, port):
        sim.network.max_connections = 20
        sim.network.handshake_timeout = 60.0
        idle = [socket.create_connection(("127.0.0.1", port)) for _ in range(30)]
        wait_until(lambda: sum(closed_by_peer(s) for s in idle) == 10)  # the oldest silent ones made room
        assert len(sim.network.connections) == 20
        assert any("closed without a handshake to make room" in r.message for r in caplog.records)
        assert ProgramClient(port).hello()[1] == 1  # and a real program gets in
        for sock in idle:
            sock.close()


def test_past_the_cap_of_real_programs_a_connection_is_refused_and_logged(caplog):
    caplog.set_level(logging.WARNING, logger="eyesim.net")
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180)))) as (sim, port):
        sim.network.max_connections = 2
        programs = [ProgramClient(port), ProgramClient(port)]
        assert [p.hello()[1] for p in programs] == [1, 2]
        extra = socket.create_connection(("127.0.0.1", port))
        wait_until(lambda: closed_by_peer(extra))
        assert any("refused a program connection" in r.message for r in caplog.records)
        assert programs[0].call("PSD_GET", 1)[0] > 0


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


def test_running_out_of_descriptors_rests_instead_of_spinning(tmp_path):
    """A simulator with few descriptors left: accepting rests (and says so) instead of waking on a
    listener it cannot serve, and programs get in again once sockets are closed."""
    log_path = tmp_path / "simulator.log"
    with open(log_path, "w") as log_file:
        simulator = subprocess.Popen(
            eyesim_command("run", "--headless", "--clock", "realtime", "--port", "0"),
            stdout=subprocess.PIPE,
            stderr=log_file,
            text=True,
            preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_NOFILE, (64, 64)),
        )
    held = []
    try:
        port = None
        for line in simulator.stdout:
            match = re.search(r"programs connect to [\d.]+:(\d+)", line)
            if match:
                port = int(match.group(1))
                break
        assert port, "the simulator printed no port"
        for _ in range(120):  # more than it has descriptors for: the kernel queues the rest
            held.append(socket.create_connection(("127.0.0.1", port), timeout=5))
        wait_until(lambda: "out of file descriptors" in log_path.read_text())
        for sock in held:
            sock.close()
        held.clear()
        wait_until(lambda: _hello_works(port))
        assert simulator.poll() is None
    finally:
        for sock in held:
            sock.close()
        simulator.kill()
        simulator.wait()


def _hello_works(port: int) -> bool:
    try:
        return ProgramClient(port).hello()[1] == 1
    except (OSError, RemoteError):
        return False
