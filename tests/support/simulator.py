"""An in-process simulator (the engine, serving its program sockets, on a thread of its own) for tests."""

from __future__ import annotations

import contextlib
import threading

from eyesim.core.clock import Clock
from eyesim.core.engine import Simulation
from eyesim.net.program_server import ProgramServer
from eyesim.net.program_token import token_file_path


_tokens: dict[int, str] = {}  # port -> program token of the simulations running in this process


def token_for(port: int) -> str:
    """The program token the test clients and programs send in their HELLO: the in-process
    simulator's on `port`, else (an `eyesim run` process) the token file of the run on that port,
    as libeyesim reads it; '' for none."""
    if port in _tokens:
        return _tokens[port]
    try:
        return token_file_path(port).read_text(encoding="ascii").strip()
    except OSError:
        return ""


@contextlib.contextmanager
def running_simulation(scene, mode: str = "realtime", speed: float = 1.0, expect=(), require_token: bool = True):
    """Yield (sim, port) with the simulation loop running; stops everything afterwards. Programs
    need the run's program token (token_for(port), sim.program_token) unless not `require_token`.

    `expect`: robot ids whose program will connect; deterministic time waits for them, as it
    does for the programs `eyesim run` launches."""
    sim = Simulation(scene, Clock(mode, speed))
    sim.expected_programs.update(expect)
    server = ProgramServer(sim, "127.0.0.1", 0, require_token=require_token)
    server.start()
    if server.token is not None:
        _tokens[server.port] = server.token
    errors = []

    def loop():
        try:
            sim.run()
        except BaseException as error:  # surfaced by the test below
            errors.append(error)

    thread = threading.Thread(target=loop, daemon=True)
    thread.start()
    try:
        yield sim, server.port
    finally:
        sim.stop()
        thread.join(timeout=10)
        sim.shutdown_programs()
        server.stop()
        _tokens.pop(server.port, None)
    assert not errors, errors
