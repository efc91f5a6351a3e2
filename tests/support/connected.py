"""A protocol client connected to robot 1 of an in-process simulator, for the command tests."""

from __future__ import annotations

import contextlib

from support.client import ProgramClient
from support.scenes import arena
from support.simulator import running_simulation


@contextlib.contextmanager
def connected_program(scene=None, mode: str = "deterministic"):
    """Yield (sim, client): the client has done its handshake and drives robot 1."""
    with running_simulation(scene or arena(), mode) as (sim, port):
        client = ProgramClient(port)
        client.hello("1")
        try:
            yield sim, client
        finally:
            client.close()
