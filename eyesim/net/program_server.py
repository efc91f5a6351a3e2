"""TCP server for RoBIOS programs: framing and decoding on the I/O thread, work to the simulation.

Reading: the asyncio loop on the I/O thread reads each non-blocking socket, reassembles frames per
connection (a client that sends half a frame and stalls holds up nobody else) and queues complete
requests for the simulation thread. A malformed request gets an error reply; a frame that breaks
the framing (oversized, too short) gets an error reply and closes that one connection.

Writing: the simulation thread sends replies straight into the non-blocking socket, which saves a
thread hop per call; whatever the kernel does not take at once is queued and flushed by the I/O
loop, so the simulation never waits for a slow reader and replies keep their order."""

from __future__ import annotations

import asyncio
import errno
import logging
import socket
import threading

from eyesim.protocol import FrameDecoder, ProtocolError, decode_payload, encode_error, generated as g
from eyesim.session import Request, Session

log = logging.getLogger("eyesim.net")
READ_SIZE = 256 * 1024


class ProgramConnection:
    """One program's socket. `send` and `close` may be called from any thread."""

    def __init__(self, sim, loop: asyncio.AbstractEventLoop, sock: socket.socket, peer: str):
        self.sim = sim
        self.loop = loop
        self.sock = sock
        self.decoder = FrameDecoder()
        self._lock = threading.Lock()
        self._backlog = bytearray()  # bytes the kernel has not taken yet, flushed by the I/O loop
        self._closed = False
        self.session = Session(connection=self, peer=peer)

    def open(self) -> None:
        self.sim.connect(self.session)
        self.loop.add_reader(self.sock, self._on_readable)

    # -- any thread ----------------------------------------------------------------------------
    def send(self, data: bytes) -> None:
        with self._lock:
            if self._closed:
                return
            if not self._backlog:
                try:
                    sent = self.sock.send(data)
                except BlockingIOError:
                    sent = 0
                except OSError:
                    return  # the reader side notices the broken connection and cleans up
                if sent == len(data):
                    return
                data = data[sent:]
                self.loop.call_soon_threadsafe(self._watch_writable)
            self._backlog += data

    def close(self) -> None:
        self.loop.call_soon_threadsafe(self._shutdown)

    # -- I/O thread ----------------------------------------------------------------------------
    def _watch_writable(self) -> None:
        if not self._closed:
            self.loop.add_writer(self.sock, self._on_writable)

    def _on_writable(self) -> None:
        with self._lock:
            try:
                sent = self.sock.send(self._backlog)
            except BlockingIOError:
                return
            except OSError:
                sent = len(self._backlog)
            del self._backlog[:sent]
            if not self._backlog:
                self.loop.remove_writer(self.sock)

    def _on_readable(self) -> None:
        try:
            data = self.sock.recv(READ_SIZE)
        except BlockingIOError:
            return
        except OSError as error:
            if error.errno != errno.ECONNRESET:
                log.warning("%s: %s", self.session.peer, error)
            data = b""
        if not data:
            self._shutdown()
            return
        try:
            messages = self.decoder.feed(data)
        except ProtocolError as error:
            log.warning("%s: %s; closing the connection", self.session.peer, error)
            self.send(encode_error(0, 0, error.code, str(error)))
            self._shutdown(flush=True)
            return
        for message in messages:
            self._dispatch(message)

    def _dispatch(self, message) -> None:
        op = g.OPS.get(message.op)
        if op is None:
            self.send(encode_error(message.op, message.request_id, g.ERR_UNKNOWN_OP,
                                   f"unknown operation {message.op}"))
            return
        if message.kind != g.KIND_REQUEST:
            self.send(encode_error(message.op, message.request_id, g.ERR_BAD_FRAME,
                                   f"{op.name}: programs may only send requests (kind {g.KIND_REQUEST}), "
                                   f"not kind {message.kind}"))
            return
        try:
            args = decode_payload(op.request, message.payload)
        except ProtocolError as error:
            self.send(encode_error(message.op, message.request_id, error.code, f"{op.name}: {error}"))
            return
        self.sim.submit(Request(self.session, op, message.request_id, args))

    def _shutdown(self, flush: bool = False) -> None:
        with self._lock:
            if self._closed:
                return
            self._closed = True
            if flush and self._backlog:
                try:
                    self.sock.setblocking(True)
                    self.sock.settimeout(1.0)
                    self.sock.sendall(self._backlog)
                except OSError:
                    pass
        self.loop.remove_reader(self.sock)
        self.loop.remove_writer(self.sock)
        self.sock.close()
        self.sim.disconnect(self.session)


class ProgramServer:
    """Listens for programs on host:port (port 0 = any free port; see `port` once started)."""

    def __init__(self, sim, io_thread, host: str = g.DEFAULT_HOST, port: int = g.DEFAULT_PORT):
        self.sim = sim
        self.io = io_thread
        self.host = host
        self.port = port
        self._listener: socket.socket | None = None
        self._accepting: asyncio.Task | None = None

    def start(self) -> None:
        """Bind and start accepting; raises OSError (e.g. port in use) in the caller's thread."""
        listener = socket.create_server((self.host, self.port), reuse_port=False)
        listener.setblocking(False)
        self._listener = listener
        self.port = listener.getsockname()[1]
        self.io.run(self._start())

    async def _start(self) -> None:
        self._accepting = asyncio.get_running_loop().create_task(self._accept_loop())

    async def _accept_loop(self) -> None:
        loop = asyncio.get_running_loop()
        while True:
            sock, address = await loop.sock_accept(self._listener)
            sock.setblocking(False)
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            connection = ProgramConnection(self.sim, loop, sock, f"{address[0]}:{address[1]}")
            connection.open()

    def stop(self) -> None:
        if self._listener is not None:
            self.io.run(self._stop())

    async def _stop(self) -> None:
        if self._accepting is not None:
            self._accepting.cancel()
        self._listener.close()
