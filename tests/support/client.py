"""A minimal blocking protocol client, for tests and benchmarks of the program server."""

from __future__ import annotations

import socket

from eyesim.protocol import FrameDecoder, decode_payload, encode_message, generated as g

from support.simulator import token_for


class RemoteError(Exception):
    def __init__(self, code: int, message: str):
        super().__init__(f"[{code}] {message}")
        self.code = code
        self.message = message


class ProgramClient:
    """`token`: the program token its HELLO sends; by default the one of the in-process simulator
    on `port` (support.simulator.token_for)."""

    def __init__(self, port: int, host: str = "127.0.0.1", timeout: float = 10.0, token: str | None = None):
        self.token = token_for(port) if token is None else token
        self.sock = socket.create_connection((host, port), timeout=timeout)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.decoder = FrameDecoder()
        self.next_id = 0
        self.inbox = []

    def hello(self, robot: str = "", program: str = "test") -> tuple:
        return self.call("HELLO", g.VERSION, robot, program, 0, self.token)

    def send(self, name: str, *args) -> int:
        self.next_id += 1
        op = g.OPS_BY_NAME[name]
        self.sock.sendall(encode_message(op.code, g.KIND_REQUEST, self.next_id, args))
        return self.next_id

    def receive(self):
        """The next message from the server (Message)."""
        while not self.inbox:
            data = self.sock.recv(65536)
            if not data:
                raise ConnectionError("the simulator closed the connection")
            self.inbox += self.decoder.feed(data)
        return self.inbox.pop(0)

    def reply(self, name: str, request_id: int) -> tuple:
        message = self.receive()
        assert message.request_id == request_id, (message, request_id)
        if message.kind == g.KIND_ERROR:
            raise RemoteError(*decode_payload(g.ERROR_PAYLOAD, message.payload))
        return decode_payload(g.OPS_BY_NAME[name].reply, message.payload)

    def call(self, name: str, *args) -> tuple:
        return self.reply(name, self.send(name, *args))

    def close(self) -> None:
        self.sock.close()
