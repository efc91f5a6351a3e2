"""Fixtures for the C library tests: building libeyesim, compiling C programs, a fake simulator."""

from __future__ import annotations

import fcntl
import hashlib
import heapq
import os
import shutil
import socket
import subprocess
import threading
import time
from pathlib import Path
from typing import Callable, NamedTuple

import pytest

from eyesim import paths
from eyesim.programs import toolchain
from eyesim.protocol import FrameDecoder, decode_payload, encode_error, encode_frame, encode_message, generated as g

ROOT = Path(__file__).resolve().parents[2]
DEV_PREFIX = ROOT / "build" / "robios"
DEV_BUILD = ROOT / "build" / "robios-build"
ENV_NAMES = ("EYESIM_HOST", "EYESIM_PORT", "EYESIM_ROBOT", "EYESIM_CONNECT_TIMEOUT", "EYESIM_TOKEN")


# ---- The library ------------------------------------------------------------------------------


def _installed(prefix: Path) -> bool:
    lib = prefix / "lib"
    return (prefix / "include" / "eyebot.h").is_file() and any(
        (lib / name).is_file() for name in ("libeyesim.so", "libeyesim.dylib")
    )


def _dev_build() -> None:
    """The documented development build into build/robios (incremental; locked, the tree is shared)."""
    if not shutil.which("cmake"):
        pytest.fail("cmake is needed to build the RoBIOS C library for these tests")
    DEV_BUILD.parent.mkdir(parents=True, exist_ok=True)
    steps = [["cmake", "--build", str(DEV_BUILD)], ["cmake", "--install", str(DEV_BUILD), "--prefix", str(DEV_PREFIX)]]
    if not (DEV_BUILD / "CMakeCache.txt").is_file():
        steps.insert(0, ["cmake", "-S", str(ROOT / "robios"), "-B", str(DEV_BUILD), "-DEYESIM_WERROR=ON"])
    with open(DEV_BUILD.parent / "robios-build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        for step in steps:
            done = subprocess.run(step, cwd=ROOT, capture_output=True, text=True)
            if done.returncode:
                pytest.fail(f"{' '.join(step)} failed:\n{done.stdout}\n{done.stderr}")


@pytest.fixture(scope="session")
def robios_prefix() -> Path:
    """Where libeyesim and eyebot.h are: EYESIM_ROBIOS, else the installed package; the dev build
    in build/robios is (re)built first when it is the one in use or nothing is installed."""
    prefix = paths.robios_dir()
    if prefix.resolve() == DEV_PREFIX.resolve() or (not os.environ.get("EYESIM_ROBIOS") and not _installed(prefix)):
        _dev_build()
        return DEV_PREFIX
    if not _installed(prefix):
        pytest.fail(f"EYESIM_ROBIOS={prefix} holds no built library (include/eyebot.h, lib/libeyesim.so)")
    return prefix


# ---- Compiling and running C programs ---------------------------------------------------------


class Compiler:
    """Compiles program sources with `eyesim cc` / `eyesim c++` (cached by source and flags)."""

    def __init__(self, prefix: Path, out_dir: Path):
        self.prefix = prefix
        self.out_dir = out_dir

    def build(self, source: str, name: str = "prog", language: str = "cc", flags: tuple[str, ...] = ()) -> Path:
        digest = hashlib.sha1(f"{language}{flags}{source}".encode()).hexdigest()[:10]
        work = self.out_dir / f"{name}-{digest}"
        exe = work / name
        if exe.exists():
            return exe
        work.mkdir(parents=True, exist_ok=True)
        src = work / (f"{name}.c" if language == "cc" else f"{name}.cpp")
        src.write_text(source)
        flags = ("-std=c11",) if language == "cc" and not flags else flags
        command = toolchain.compiler_command(
            language, [*flags, "-Wall", "-Wextra", "-Werror", str(src), "-o", str(exe)], self.prefix
        )
        done = subprocess.run(command, capture_output=True, text=True)
        assert done.returncode == 0, f"{' '.join(command)}\n{done.stdout}{done.stderr}"
        return exe


@pytest.fixture(scope="session")
def compiler(robios_prefix, tmp_path_factory) -> Compiler:
    return Compiler(robios_prefix, tmp_path_factory.mktemp("programs"))


def program_env(**extra: str) -> dict[str, str]:
    """The environment for a robot program: ours without any EYESIM_* connection settings, plus `extra`."""
    env = {k: v for k, v in os.environ.items() if k not in ENV_NAMES and k != "LD_LIBRARY_PATH"}
    env["EYESIM_CONNECT_TIMEOUT"] = "5"  # no test should hang for the default 10 s
    env.update(extra)
    return env


def free_port() -> int:
    """A local port nothing listens on (released again, so very likely still free)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


# ---- The fake simulator -----------------------------------------------------------------------


class Error(NamedTuple):
    """Answer with an error reply."""

    code: int
    message: str


class Delay(NamedTuple):
    """Answer after `seconds` (lets replies overtake each other)."""

    seconds: float
    values: tuple


class Raw(NamedTuple):
    """Answer with a reply frame carrying these payload bytes as they are (malformed on purpose)."""

    payload: bytes


class Garbage(NamedTuple):
    """Answer with these bytes instead of a frame (a broken simulator)."""

    data: bytes


HOLD = "hold"  # keep the request unanswered until the test calls release()


class Request(NamedTuple):
    op: str
    values: tuple
    request_id: int


class Connection:
    def __init__(self, sock: socket.socket):
        self.sock = sock
        self.send_lock = threading.Lock()
        self.hello: tuple | None = None

    def send(self, frame: bytes) -> None:
        with self.send_lock:
            try:
                self.sock.sendall(frame)
            except OSError:
                pass  # the program is gone; the test sees that through its exit status

    def close(self) -> None:
        try:
            self.sock.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self.sock.close()


class FakeSimulator:
    """A stand-in for the simulator: accepts the handshake, records every request and answers it by
    `script` (op name -> values | Error | Delay | Raw | Garbage | HOLD | function of the request values).
    Ops not in the script get all-zero replies."""

    Error, Delay, Raw, Garbage, HOLD = Error, Delay, Raw, Garbage, HOLD

    def __init__(self, port: int = 0, hello: Error | str | None = None):
        self.script: dict[str, object] = {}
        self.hello_answer = hello  # None: accept as robot 1 "S4"; Error: refuse; "close": hang up
        self.requests: list[Request] = []
        self.hellos: list[tuple] = []
        self.held: list[tuple[Connection, str, int]] = []
        self.connections: list[Connection] = []
        self.changed = threading.Condition()
        self._delayed: list[tuple[float, int, Connection, bytes]] = []
        self._delay_seq = 0
        self._closed = False
        self.listener = socket.create_server(("127.0.0.1", port))
        self.port = self.listener.getsockname()[1]
        threading.Thread(target=self._accept, daemon=True).start()
        threading.Thread(target=self._send_delayed, daemon=True).start()

    def env(self, **extra: str) -> dict[str, str]:
        return program_env(EYESIM_HOST="127.0.0.1", EYESIM_PORT=str(self.port), **extra)

    # -- what the tests look at and do --

    def wait_for(self, condition: Callable[[], bool], timeout: float = 10.0) -> bool:
        with self.changed:
            return self.changed.wait_for(condition, timeout)

    def ops(self) -> list[str]:
        with self.changed:
            return [r.op for r in self.requests]

    def count(self, op: str) -> int:
        with self.changed:
            return sum(1 for r in self.requests if r.op == op)

    def held_ops(self) -> list[str]:
        with self.changed:
            return [op for _, op, _ in self.held]

    def release(self, op: str, values: tuple) -> None:
        """Answers the oldest held request of `op`."""
        with self.changed:
            index = next(k for k, (_, held_op, _) in enumerate(self.held) if held_op == op)
            conn, _, request_id = self.held.pop(index)
        conn.send(encode_message(g.OPS_BY_NAME[op].code, g.KIND_REPLY, request_id, values))

    def close_clients(self) -> None:
        """The simulator goes away: every program connection is closed."""
        with self.changed:
            connections = list(self.connections)
        for conn in connections:
            conn.close()

    def close(self) -> None:
        self._closed = True
        self.listener.close()
        self.close_clients()
        with self.changed:
            self.changed.notify_all()

    # -- serving --

    def _accept(self) -> None:
        while True:
            try:
                sock, _ = self.listener.accept()
            except OSError:
                return
            conn = Connection(sock)
            with self.changed:
                self.connections.append(conn)
            threading.Thread(target=self._serve, args=(conn,), daemon=True).start()

    def _serve(self, conn: Connection) -> None:
        decoder = FrameDecoder()
        while True:
            try:
                data = conn.sock.recv(65536)
            except OSError:
                return
            if not data:
                return
            for message in decoder.feed(data):
                spec = g.OPS[message.op]
                values = decode_payload(spec.request, message.payload)
                if conn.hello is None:
                    assert spec.name == "HELLO", f"first frame was {spec.name}"
                    conn.hello = values
                    with self.changed:
                        self.hellos.append(values)
                        self.changed.notify_all()
                    if not self._answer_hello(conn, message.request_id):
                        return
                    continue
                self._answer(conn, spec.name, values, message.request_id)

    def _answer_hello(self, conn: Connection, request_id: int) -> bool:
        if self.hello_answer == "close":
            conn.close()
            return False
        if isinstance(self.hello_answer, Error):
            conn.send(encode_error(g.OP_HELLO, request_id, *self.hello_answer))
            conn.close()
            return False
        conn.send(encode_message(g.OP_HELLO, g.KIND_REPLY, request_id, (g.VERSION, 1, "S4")))
        return True

    def _answer(self, conn: Connection, op: str, values: tuple, request_id: int) -> None:
        spec = g.OPS_BY_NAME[op]
        answer = self.script.get(op, tuple(0 for _ in spec.reply))
        if callable(answer):
            answer = answer(values)
        with self.changed:
            self.requests.append(Request(op, values, request_id))
            if answer == HOLD:
                self.held.append((conn, op, request_id))
            self.changed.notify_all()
        if answer == HOLD:
            return
        if isinstance(answer, Error):
            conn.send(encode_error(spec.code, request_id, *answer))
        elif isinstance(answer, Garbage):
            conn.send(answer.data)
        elif isinstance(answer, Raw):
            conn.send(encode_frame(spec.code, g.KIND_REPLY, request_id, answer.payload))
        elif isinstance(answer, Delay):
            frame = encode_message(spec.code, g.KIND_REPLY, request_id, answer.values)
            with self.changed:
                self._delay_seq += 1
                heapq.heappush(self._delayed, (time.monotonic() + answer.seconds, self._delay_seq, conn, frame))
                self.changed.notify_all()
        else:
            conn.send(encode_message(spec.code, g.KIND_REPLY, request_id, tuple(answer)))

    def _send_delayed(self) -> None:
        while not self._closed:
            with self.changed:
                now = time.monotonic()
                due = []
                while self._delayed and self._delayed[0][0] <= now:
                    due.append(heapq.heappop(self._delayed))
                if not due:
                    wait = self._delayed[0][0] - now if self._delayed else 0.1
                    self.changed.wait(min(wait, 0.1))
                    continue
            for _, _, conn, frame in due:
                conn.send(frame)


@pytest.fixture
def fake_sim():
    sim = FakeSimulator()
    yield sim
    sim.close()


@pytest.fixture
def make_fake_sim():
    """For tests that need a fake with particular settings: make_fake_sim(port=..., hello=...)."""
    made = []

    def make(**kwargs) -> FakeSimulator:
        made.append(FakeSimulator(**kwargs))
        return made[-1]

    yield make
    for sim in made:
        sim.close()


@pytest.fixture
def unused_port() -> int:
    return free_port()


@pytest.fixture
def free_port_env(unused_port) -> dict[str, str]:
    """A program environment pointing at a port where no simulator listens (short timeout)."""
    return program_env(EYESIM_HOST="127.0.0.1", EYESIM_PORT=str(unused_port), EYESIM_CONNECT_TIMEOUT="0.5")


@pytest.fixture
def env_for():
    """program_env as a fixture: env_for(EYESIM_PORT="1234", ...)."""
    return program_env
