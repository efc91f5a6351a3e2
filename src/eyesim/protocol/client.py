"""The one Python client of the program protocol: a blocking connection that sends requests and
reads their replies in order, as libeyesim does. Used by programs written as Python callables
(eyesim.testing.callable_program) and by the tests and benchmarks of the program server."""

from __future__ import annotations

import socket

from eyesim.protocol import generated as g
from eyesim.protocol.codec import FrameDecoder, Message, decode_payload, encode_message


class RemoteError(Exception):
    """The simulator answered a call with an error reply."""

    def __init__(self, code: int, message: str):
        super().__init__(f"[{code}] {message}")
        self.code = code
        self.message = message


class ProtocolClient:
    """One connection to the program port. `send` may pipeline requests; `reply` reads the next
    reply, which must answer the request named (replies come in request order)."""

    def __init__(self, port: int, host: str = "127.0.0.1", timeout: float | None = None):
        self.sock = socket.create_connection((host, port), timeout=timeout)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.decoder = FrameDecoder()
        self.next_id = 0
        self.inbox: list[Message] = []

    def send(self, name: str, *args) -> int:
        self.next_id += 1
        self.sock.sendall(encode_message(g.OPS_BY_NAME[name].code, g.KIND_REQUEST, self.next_id, args))
        return self.next_id

    def receive(self) -> Message:
        """The next message from the simulator."""
        while not self.inbox:
            data = self.sock.recv(65536)
            if not data:
                raise ConnectionError("the simulator closed the connection")
            self.inbox += self.decoder.feed(data)
        return self.inbox.pop(0)

    def reply(self, name: str, request_id: int) -> tuple:
        message = self.receive()
        if message.request_id != request_id:
            raise ConnectionError(f"a reply to request {message.request_id} came where {request_id}'s was due")
        if message.kind == g.KIND_ERROR:
            raise RemoteError(*decode_payload(g.ERROR_PAYLOAD, message.payload))
        return decode_payload(g.OPS_BY_NAME[name].reply, message.payload)

    def call(self, name: str, *args) -> tuple:
        return self.reply(name, self.send(name, *args))

    def close(self) -> None:
        try:
            self.sock.shutdown(socket.SHUT_RDWR)  # wakes a thread of ours waiting in recv
        except OSError:
            pass
        self.sock.close()
