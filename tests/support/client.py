"""The protocol client of the tests and benchmarks: eyesim.protocol.client with the program token of
the in-process simulator and a HELLO helper."""

from __future__ import annotations

from eyesim.protocol import generated as g
from eyesim.protocol.client import ProtocolClient, RemoteError

from support.simulator import token_for

__all__ = ["ProgramClient", "RemoteError"]


class ProgramClient(ProtocolClient):
    """`token`: the program token its HELLO sends; by default the one of the in-process simulator
    on `port` (support.simulator.token_for)."""

    def __init__(self, port: int, host: str = "127.0.0.1", timeout: float = 10.0, token: str | None = None):
        super().__init__(port, host, timeout)
        self.token = token_for(port) if token is None else token

    def hello(self, robot: str = "", program: str = "test") -> tuple:
        return self.call("HELLO", g.VERSION, robot, program, 0, self.token)
