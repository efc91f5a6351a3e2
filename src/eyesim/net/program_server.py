"""TCP server for RoBIOS programs, served by the simulation thread itself (docs/architecture.md).

The simulation thread waits on the program sockets with a selector between physics steps: a
request is read, decoded, carried out and answered on that one thread, with no hand-off between
threads (each hand-off cost as much as the loopback round trip itself). Other threads reach the
simulation through its inbox and wake the selector through a socket pair. The selector also
watches the launched programs' output pipes (programs/program_output.py).

Every socket is non-blocking. A connection reassembles its own frames, so a client that sends half
a frame and stalls holds up nobody. Replies go straight into the socket; what the kernel does not
take at once waits in that connection's backlog, flushed when the socket is writable, so the
simulation never waits for a slow reader. A large reply (a camera image) goes SEND_PIECE bytes
per turn of the loop, so other programs are served between its pieces (the kernel's copy of a
whole 15 MB frame held the simulation thread for 2-4 ms). Two limits keep one program from sinking the rest:
while a connection has MAX_QUEUED requests waiting (queued or in blocking calls) or more than
READ_PAUSE_BACKLOG bytes of replies unread, its socket is not read (TCP holds the sender back); a program that stops reading
its replies for STALL_TIMEOUT, or lets them pile up beyond MAX_BACKLOG, is disconnected with a
logged reason, and its buffers are given back. A run holds at most MAX_CONNECTIONS connections
(past it, the oldest that has not said HELLO makes room, or the new one is refused, and logged);
one that has not sent its handshake within HANDSHAKE_TIMEOUT is closed; and when the process runs out of descriptors, accepting rests for a second instead of
spinning on a listener it cannot serve. A connection whose socket is not being read cannot see its
program close it (the end of the stream waits behind unread requests): on Linux the socket's TCP
state shows it, looked at once a second, so a program that pipelined blocking calls and left
frees its robot and descriptor; and one that sends more while MAX_QUEUED of its calls wait (keys,
times) is closed with an error: those calls could wait for ever, and the requests behind them
would hide its close. Warnings about single connections, which a client can cause by the thousand,
are logged in full once a second per reason and otherwise counted (repeated_warnings.py)."""

from __future__ import annotations

import errno
import logging
import os
import selectors
import socket
import time

from eyesim.net import program_token
from eyesim.net.backlog import Backlog
from eyesim.net.repeated_warnings import RepeatedWarnings
from eyesim.net.session import Deferred, Request, Session
from eyesim.protocol import FrameDecoder, ProtocolError, decode_payload, encode_error, generated as g

log = logging.getLogger("eyesim.net")
READ_SIZE = 256 * 1024
SEND_PIECE = 256 * 1024  # bytes handed to the kernel at once (tens of µs to copy)
MAX_QUEUED = 64  # requests of one program waiting for the simulation before its socket rests
READ_PAUSE_BACKLOG = 1 << 20  # bytes of unread replies before a program's requests are not read
MAX_BACKLOG = 32 << 20  # bytes of unread replies that close the connection (two largest frames)
READ, WRITE = selectors.EVENT_READ, selectors.EVENT_WRITE
STALL_TIMEOUT = 30.0  # s a program may leave its replies unread (a debugger's breakpoint) before it is dropped
MAX_CONNECTIONS = 256  # open program connections of one run (a class's robots are far fewer)
HANDSHAKE_TIMEOUT = 5.0  # s from connecting to the HELLO before a connection is closed
ACCEPT_REST = 1.0  # s the listeners rest after the process ran out of file descriptors
TCP_CLOSE_WAIT = 8  # Linux's TCP state once the peer has closed its end (include/net/tcp_states.h)


def version_refusal(version: int) -> str:
    return (
        f"protocol version {version} is not supported; this simulator speaks version {g.VERSION} "
        f"(rebuild the program with this EyeSim's `eyesim cc`)"
    )


def peer_closed(sock: socket.socket) -> bool:
    """Whether the program has closed its end, seen without reading the socket; False where the
    system does not tell (only Linux has TCP_INFO)."""
    if not hasattr(socket, "TCP_INFO"):
        return False
    try:
        return sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_INFO, 1)[0] == TCP_CLOSE_WAIT
    except OSError:
        return False


def hello_version(message) -> int | None:
    """The protocol version a HELLO starts with (every version's HELLO does), or None."""
    if message.op != g.OP_HELLO or len(message.payload) < 4:
        return None
    return int.from_bytes(bytes(message.payload[:4]), "little")


class ProgramConnection:
    """One program's socket; used only on the simulation thread."""

    def __init__(self, sockets: "SimulationEventLoop", sock: socket.socket, peer: str):
        self.sockets = sockets
        self.sock = sock
        self.decoder = FrameDecoder()
        self.backlog = Backlog()  # reply bytes the kernel has not taken yet
        self.closed = False
        self.session = Session(connection=self, peer=peer)
        self._events = READ
        self.backlog_progress = 0.0  # wall time (monotonic) the backlog last began or shrank
        self.connected_at = time.monotonic()

    # -- replies -------------------------------------------------------------------------------
    def send(self, data: bytes | memoryview) -> None:
        if self.closed:
            return
        if not self.backlog.size:
            try:
                sent = self.sock.send(data if len(data) <= SEND_PIECE else memoryview(data)[:SEND_PIECE])
            except BlockingIOError:
                sent = 0
            except OSError:
                return  # reading notices the broken connection and closes it
            if sent == len(data):
                return
            data = memoryview(data)[sent:]
        if self.backlog.size + len(data) > MAX_BACKLOG:
            self.sockets.warnings.warn(
                "closed: too many replies unread",
                "%s: %d bytes of replies unread; closing the connection (the program stopped reading its replies)",
                self.session.name,
                self.backlog.size + len(data),
            )
            self.close()
            return
        if not self.backlog.size:
            self.backlog_progress = time.monotonic()
        self.backlog += data
        self.update_interest()

    def flush(self) -> None:
        try:
            sent = self.sock.send(self.backlog.first()[:SEND_PIECE])
        except BlockingIOError:
            return
        except OSError:
            sent = self.backlog.size
        if sent:
            self.backlog_progress = time.monotonic()
        self.backlog.consume(sent)
        self._refill()  # requests held back while the replies piled up; no more writing once all went

    # -- requests ------------------------------------------------------------------------------
    def read(self) -> None:
        try:
            data = self.sock.recv(READ_SIZE)
        except BlockingIOError:
            return
        except OSError as error:
            if error.errno != errno.ECONNRESET:
                log.warning("%s: %s", self.session.peer, error)
            data = b""
        if not data:
            self.close()
            return
        self._take(data)

    def _take(self, data: bytes) -> None:
        """Decode requests up to the queue limit; the rest stays buffered until there is room."""
        try:
            messages = self.decoder.feed(data, limit=MAX_QUEUED - self.held())
        except ProtocolError as error:
            self.sockets.warnings.warn(
                "closed: a malformed frame", "%s: %s; closing the connection", self.session.peer, error
            )
            self.send(encode_error(0, 0, error.code, str(error)))
            self.close(flush=True)
            return
        for message in messages:
            self._dispatch(message)
        self.update_interest()

    def _dispatch(self, message) -> None:
        op = g.OPS.get(message.op)
        if op is None:
            self.send(encode_error(message.op, message.request_id, g.ERR_UNKNOWN_OP, f"unknown operation {message.op}"))
            return
        if message.kind != g.KIND_REQUEST:
            self.send(
                encode_error(
                    message.op,
                    message.request_id,
                    g.ERR_BAD_FRAME,
                    f"programs may only send requests (kind {g.KIND_REQUEST}), not kind {message.kind}",
                )
            )
            return
        try:
            args = decode_payload(op.request, message.payload, op.lengths)
        except ProtocolError as error:
            code, text = error.code, str(error)
            version = hello_version(message)
            if error.code == g.ERR_BAD_PAYLOAD and version not in (None, g.VERSION):  # an older HELLO's fields
                code, text = g.ERR_VERSION, version_refusal(version)
            self.send(encode_error(message.op, message.request_id, code, text))
            return
        self.sockets.deliver(Request(self.session, op, message.request_id, args))

    # -- selector interest -----------------------------------------------------------------------
    def resume(self) -> None:
        """The simulation took a request: decode what is buffered, and read again when there is room.
        As a rule the socket is being read and nothing waits in the decoder: nothing changes then."""
        if self._events & READ and not self.decoder.pending_bytes:
            return
        self._refill()

    def _refill(self) -> None:
        if not self.closed and self.decoder.pending_bytes:
            if self._has_room():
                self._take(b"")
            elif self._all_waiting():
                self._refuse_more_waits()
                return
        self.update_interest()

    def _all_waiting(self) -> bool:
        """Every request the cap holds is a blocking call waiting for its condition (a key, a time),
        none is to be served: the requests behind them could wait for ever."""
        session = self.session
        return (
            not session.queued
            and len(session.pending) >= MAX_QUEUED
            and not any(isinstance(pending, Deferred) for _, pending in session.pending)
        )

    def _refuse_more_waits(self) -> None:
        """More calls than MAX_QUEUED waiting at once: no program makes them (one call at a time per
        thread), and unread they would hide the program's close, keeping its robot taken."""
        text = (
            f"more than {MAX_QUEUED} calls waiting at once (a program makes one call at a time per "
            f"thread); closing the connection"
        )
        self.sockets.warnings.warn(
            f"closed: more than {MAX_QUEUED} calls waiting at once", "%s: %s", self.session.name, text
        )
        self.send(encode_error(0, 0, g.ERR_NOT_SUPPORTED, text))
        self.close(flush=True)

    def reading(self) -> bool:
        return bool(self._events & READ)

    def held(self) -> int:
        """Requests of this program the simulation holds: queued, and waiting in blocking calls
        (5,000 pipelined KEYWait requests were once all taken)."""
        return len(self.session.queued) + len(self.session.pending)

    def _has_room(self) -> bool:
        return self.held() < MAX_QUEUED and self.backlog.size < READ_PAUSE_BACKLOG

    def update_interest(self) -> None:
        """Read while the program's queue and unread replies are small; write while replies wait."""
        if self.closed:
            return
        events = READ if self._has_room() else 0
        if self.backlog.size:
            events |= WRITE
        if events == self._events:
            return
        selector = self.sockets.selector
        if not self._events:
            selector.register(self.sock, events, self)
        elif not events:
            selector.unregister(self.sock)
        else:
            selector.modify(self.sock, events, self)
        self._events = events

    def close(self, flush: bool = False) -> None:
        if self.closed:
            return
        self.closed = True
        if flush and self.backlog.size:
            # What the kernel takes now (the error reply, as a rule); never a wait on the simulation
            # thread: a program that stopped reading would hold every other program up.
            try:
                for chunk in self.backlog.chunks():
                    if self.sock.send(chunk) < len(chunk):
                        break
            except OSError:
                pass
        self.backlog = Backlog()  # given back at once, not when the session is forgotten
        if self._events:
            self._events = 0
            try:
                self.sockets.selector.unregister(self.sock)
            except (KeyError, ValueError):
                pass  # Ctrl-C came between a change of interest and its note (closing after it)
        self.sock.close()
        self.sockets.closed(self)


class SimulationEventLoop:
    """The simulation thread's event loop: the selector it waits on between steps, for listeners,
    program connections and a wake-up socket pair for the other threads. `deliver(request)`, `connected(session)` and
    `disconnected(session)` are the simulation's, called on its thread."""

    def __init__(self, deliver, connected, disconnected):
        self.selector = selectors.DefaultSelector()
        self.deliver = deliver
        self._connected = connected
        self._disconnected = disconnected
        self._wake_read, self._wake_write = socket.socketpair()
        self._wake_read.setblocking(False)
        self._wake_write.setblocking(False)
        self.selector.register(self._wake_read, READ, None)
        self.connections: set[ProgramConnection] = set()
        self._last_stall_check = time.monotonic()
        self.max_connections = MAX_CONNECTIONS
        self.handshake_timeout = HANDSHAKE_TIMEOUT
        self._listeners: set[socket.socket] = set()
        self._resting_until = 0.0  # the listeners are unregistered until then (no descriptors left)
        self.warnings = RepeatedWarnings(log)  # per-connection warnings, summed up once a second

    def wake(self) -> None:
        """Any thread: make a waiting `poll` return."""
        try:
            self._wake_write.send(b"\0")
        except (BlockingIOError, OSError):
            pass  # already woken (the pair's buffer is full) or shut down

    def add_listener(self, listener: socket.socket) -> None:
        self._listeners.add(listener)
        if not self._resting_until:
            self.selector.register(listener, READ, listener)

    def remove_listener(self, listener: socket.socket) -> None:
        self._listeners.discard(listener)
        if not self._resting_until:
            self.selector.unregister(listener)
        listener.close()

    def watch(self, file, on_readable) -> None:
        """Call `on_readable()` on this thread whenever `file` has data (a program's output pipe)."""
        self.selector.register(file, READ, on_readable)

    def unwatch(self, file) -> None:
        try:
            self.selector.unregister(file)
        except (KeyError, ValueError):
            pass  # not watched (any more)

    def poll(self, timeout: float | None) -> None:
        """Wait up to `timeout` seconds (0: just look) for sockets, then serve what is ready."""
        for key, events in self.selector.select(timeout):
            target = key.data
            if target is None:
                self._drain_wake()
            elif isinstance(target, socket.socket):
                self._accept(target)
            elif not isinstance(target, ProgramConnection):
                target()  # a watched file
            else:
                if events & WRITE and not target.closed:
                    target.flush()
                if events & READ and not target.closed:
                    target.read()
        now = time.monotonic()
        if now - self._last_stall_check >= 1.0 or (self._resting_until and now >= self._resting_until):
            self._last_stall_check = now
            self._drop_stalled(now)
            self._end_rest(now)
            self.warnings.summarize(now)

    def _drop_stalled(self, now: float) -> None:
        for connection in list(self.connections):
            if connection.backlog.size and now - connection.backlog_progress > STALL_TIMEOUT:
                self.warnings.warn(
                    "closed: replies not read",
                    "%s: has not read its replies for %.0f s (%d bytes waiting); closing the connection",
                    connection.session.name,
                    now - connection.backlog_progress,
                    connection.backlog.size,
                )
                connection.close()
            elif connection.session.robot is None and now - connection.connected_at > self.handshake_timeout:
                self.warnings.warn(
                    f"closed: no handshake within {self.handshake_timeout:g} s",
                    "%s: sent no handshake within %g s; closing the connection",
                    connection.session.peer,
                    self.handshake_timeout,
                )
                connection.close()
            elif not connection.reading() and peer_closed(connection.sock):
                self.warnings.warn(
                    "closed: the program left while its calls waited",
                    "%s: closed its connection while %d of its calls waited; closing it here too",
                    connection.session.name,
                    connection.held(),
                )
                connection.close()

    def _evict_silent(self) -> bool:
        """At the cap, make room by closing the oldest connection that has not said HELLO (so sockets
        that never will cannot keep real programs out); False when every one has."""
        silent = [c for c in self.connections if c.session.robot is None]
        if not silent:
            return False
        oldest = min(silent, key=lambda c: c.connected_at)
        self.warnings.warn(
            "closed without a handshake to make room",
            "%s: closed without a handshake to make room (%d connections open, the most a run takes)",
            oldest.session.peer,
            self.max_connections,
        )
        oldest.close()
        return True

    def _rest(self) -> None:
        """Out of file descriptors: stop watching the listeners for ACCEPT_REST (the kernel keeps
        new connections in its backlog), rather than wake at once, again and again."""
        if not self._resting_until:
            log.warning(
                "out of file descriptors (%d program connections open); not accepting programs for %g s",
                len(self.connections),
                ACCEPT_REST,
            )
            for listener in self._listeners:
                self.selector.unregister(listener)
        self._resting_until = time.monotonic() + ACCEPT_REST

    def _end_rest(self, now: float) -> None:
        if self._resting_until and now >= self._resting_until:
            self._resting_until = 0.0
            for listener in self._listeners:
                self.selector.register(listener, READ, listener)

    def _drain_wake(self) -> None:
        try:
            while self._wake_read.recv(4096):
                pass
        except (BlockingIOError, OSError):
            pass

    def _accept(self, listener: socket.socket) -> None:
        try:
            sock, address = listener.accept()
        except BlockingIOError:
            return
        except OSError as error:
            if error.errno in (errno.EMFILE, errno.ENFILE, errno.ENOBUFS, errno.ENOMEM):
                self._rest()
            return
        if len(self.connections) >= self.max_connections and not self._evict_silent():
            self.warnings.warn(
                f"refused: at the cap of {self.max_connections} connections",
                "refused a program connection from %s:%s: %d are open, the most a run takes",
                address[0],
                address[1],
                self.max_connections,
            )
            sock.close()
            return
        sock.setblocking(False)
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        connection = ProgramConnection(self, sock, f"{address[0]}:{address[1]}")
        self.connections.add(connection)
        self.selector.register(sock, READ, connection)
        self._connected(connection.session)

    def closed(self, connection: ProgramConnection) -> None:
        self.connections.discard(connection)
        self._disconnected(connection.session)

    def close_all(self) -> None:
        for connection in list(self.connections):
            connection.close()

    def close(self) -> None:
        """Close every connection, the selector and the wake-up pair (the simulation is done with)."""
        self.close_all()
        self.selector.close()
        self._wake_read.close()
        self._wake_write.close()


class ProgramServer:
    """Listens for programs on host:port (port 0 = any free port; see `port` once started). The
    simulation thread accepts and serves the connections (see SimulationEventLoop).

    Every HELLO must carry the run's program token (net/program_token.py): `token`, else a new
    random one; `require_token=False` lets any program in, on loopback only (NoTokenRefused, a
    ValueError, for any other host). The token is the simulation's `program_token`."""

    def __init__(
        self,
        sim,
        host: str = g.DEFAULT_HOST,
        port: int = g.DEFAULT_PORT,
        *,
        require_token: bool = True,
        token: str | None = None,
    ):
        if not require_token:
            program_token.check_no_token(host)
        self.sim = sim
        self.host = host
        self.port = port
        self.token = (token or program_token.new_token()) if require_token else None
        sim.program_token = self.token  # before the simulation thread serves anyone
        self._listener: socket.socket | None = None

    def start(self, before_listening=None) -> None:
        """Bind and start accepting; raises OSError (e.g. port in use) in the caller's thread.
        `before_listening(port)` is called once the port is bound (so it is this run's), before
        any program can connect (eyesim run writes the token file then)."""
        family = socket.AF_INET6 if ":" in self.host else socket.AF_INET
        listener = socket.socket(family, socket.SOCK_STREAM)
        try:
            if os.name != "nt":  # as socket.create_server: a restarted run may bind at once
                listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            listener.bind((self.host, self.port))
            if before_listening is not None:
                before_listening(listener.getsockname()[1])
            listener.listen()
        except BaseException:
            listener.close()
            raise
        listener.setblocking(False)
        self._listener = listener
        self.port = listener.getsockname()[1]
        self.sim.on_loop(lambda sim: sim.network.add_listener(listener))

    def stop(self) -> None:
        if self._listener is not None:
            listener, self._listener = self._listener, None
            self.sim.on_loop(lambda sim: sim.network.remove_listener(listener))
