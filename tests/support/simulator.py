"""An in-process simulator (the engine, serving its program sockets, on a thread of its own) for tests."""

from __future__ import annotations

import contextlib
import threading

from eyesim.core.clock import Clock
from eyesim.core.engine import Simulation
from eyesim.net.program_server import ProgramServer


@contextlib.contextmanager
def running_simulation(scene, mode: str = "realtime", speed: float = 1.0, expect=()):
    """Yield (sim, port) with the simulation loop running; stops everything afterwards.

    `expect`: robot ids whose program will connect; deterministic time waits for them, as it
    does for the programs `eyesim run` launches."""
    sim = Simulation(scene, Clock(mode, speed))
    sim.expected_programs.update(expect)
    server = ProgramServer(sim, "127.0.0.1", 0)
    server.start()
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
        sim.shutdown_sessions()
        server.stop()
    assert not errors, errors
