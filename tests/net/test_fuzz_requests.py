"""Fuzzing the program sockets of a live in-process simulator: random, mutated and truncated frames
for every operation (extreme values, wrong kinds, huge strings), each from a fresh fuzzing client,
while a well-behaved program on another robot keeps getting correct answers. At the end the
simulation still steps, no handler traceback was logged and memory grew by less than 150 MB.

Derandomized, a few hundred examples: about 20 s. For a longer run set FUZZ_EXAMPLES (e.g. 20000)
and FUZZ_SEED (any integer: a new random series instead of the fixed one)."""

from __future__ import annotations

import logging
import struct
import time

import pytest
from hypothesis import given
from hypothesis import strategies as st
from support.client import ProgramClient, RemoteError
from support.error_log import ErrorLog
from support.memory import rss_mb
from support.simulator import running_simulation
from support.worlds import arena_scene, example_robot
from support.fuzz import examples, fuzz_settings

from eyesim.protocol import encode_frame, encode_payload, generated as g
from eyesim.scene.description import Wall

INT_MAX, INT_MIN, U32_MAX = 2**31 - 1, -(2**31), 2**32 - 1
EXAMPLES = examples(300)


GOOD_ROBOT = 2  # the well-behaved program's robot: in a room of its own, facing its east wall
ROOM = (3300, 2300, 3900, 2900)  # x1, y1, x2, y2 (mm): far from the values fuzzing likes (0, 2^n)
REPLY_TIMEOUT = 10.0
MEMORY_LIMIT_MB = 150


def fuzz_scene():
    x1, y1, x2, y2 = ROOM
    room = (Wall(x1, y1, x2, y1), Wall(x2, y1, x2, y2), Wall(x2, y2, x1, y2), Wall(x1, y2, x1, y1))
    return arena_scene(
        [("S4", (500, 500, 0)), ("S4", ((x1 + x2) / 2, (y1 + y2) / 2, 0)), (example_robot("Picker"), (1500, 1500, 0))],
        objects=[("Can", (1000, 2500, 0))],
        size=4000,
        walls=room,
    )


# -- values ------------------------------------------------------------------------------------------
EDGES = [
    0,
    1,
    -1,
    2,
    7,
    8,
    16,
    255,
    256,
    319,
    320,
    479,
    480,
    3600,
    65535,
    100_000,
    10_000_000,
    10_000_001,
    INT_MAX,
    INT_MIN,
    INT_MAX - 1,
    INT_MIN + 1,
]
i32 = st.sampled_from(EDGES) | st.integers(INT_MIN, INT_MAX)
u32 = st.sampled_from([0, 1, 999_999_999, 1_000_000_000, INT_MAX, U32_MAX]) | st.integers(0, U32_MAX)


def big(kind):
    """Up to 200 kB of one repeated piece: sizes the handlers must stay quick with (the bench and
    tests/net/test_worst_requests.py take the 16 MiB ones)."""
    pieces = (
        ["x", "\n", "\t\n", "é", "\r", "\x00", "ID3", "\ud7ff"]
        if kind == "str"
        else [b"\x00", b"\xff", b"\xff\xfb\x90\x64", b"RIFF\x00\x00\x00\x00WAVE"]
    )
    return st.tuples(st.sampled_from(pieces), st.integers(0, 200_000)).map(
        lambda p: (p[0] * (p[1] // len(p[0]) + 1))[: p[1]]
    )


FIELD = {
    "i32": i32,
    "u32": u32,
    "f64": st.floats(),
    "str": st.text(max_size=64) | big("str"),
    "bytes": st.binary(max_size=64) | big("bytes"),
    "i32s": st.lists(i32, max_size=64),
}
# Values that would make an example slow or hit the well-behaved program's robot; everything else
# is drawn from FIELD.
SPECIAL = {
    ("CAM_INIT", "resolution"): st.sampled_from([0, 1, 10, 6, -1]) | i32.filter(lambda r: not 2 <= r <= 5),
    ("SIM_SET_ROBOT", "id"): i32.filter(lambda i: i != GOOD_ROBOT),
}
FUZZED_OPS = sorted(g.OPS)


@st.composite
def request_frames(draw):
    """(op, request id, frame bytes) of a well-formed request with fuzzed values."""
    op = g.OPS[draw(st.sampled_from(FUZZED_OPS))]
    values = [draw(SPECIAL.get((op.name, name), FIELD[typ])) for name, typ in op.request]
    request_id = draw(st.integers(1, U32_MAX))
    return op.code, request_id, encode_frame(op.code, g.KIND_REQUEST, request_id, encode_payload(op.request, values))


@st.composite
def mutated_frames(draw):
    """A well-formed frame with its header or payload changed: another kind or op code, bytes
    flipped, cut or added. Its length field is kept right, so it is answered."""
    op, request_id, frame = draw(request_frames())
    body = bytearray(frame[4:])
    how = draw(st.sampled_from(["kind", "op", "flip", "cut", "append"]))
    if how == "kind":
        struct.pack_into("<H", body, 2, draw(st.integers(1, 65535)))
    elif how == "op":
        op = draw(st.integers(0, 65535))
        struct.pack_into("<H", body, 0, op)
    elif how == "flip" and len(body) > 8:
        for _ in range(draw(st.integers(1, 8))):
            body[draw(st.integers(8, len(body) - 1))] = draw(st.integers(0, 255))
    elif how == "cut":
        del body[8 + draw(st.integers(0, len(body) - 8)) :]
    else:
        body += draw(st.binary(min_size=1, max_size=64))
    return op, request_id, struct.pack("<I", len(body)) + bytes(body)


answered = st.one_of(request_frames(), mutated_frames())
# Input that is not one whole frame: random bytes, a frame cut short, a length beyond the limit.
unanswered = st.one_of(
    st.binary(min_size=1, max_size=300),
    request_frames().flatmap(lambda f: st.integers(1, len(f[2]) - 1).map(lambda n: f[2][:n])),
    st.integers(g.MAX_FRAME + 1, U32_MAX).map(lambda n: struct.pack("<I", n) + b"\0" * 8),
    st.integers(0, g.HEADER_SIZE - 1).map(lambda n: struct.pack("<I", n) + b"\0" * 8),
)


# -- the run ---------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def fuzz_target():
    handler = ErrorLog()
    logging.getLogger("eyesim").addHandler(handler)
    try:
        with running_simulation(fuzz_scene(), "realtime") as (sim, port):
            good = WellBehaved(port)
            good.start_mb = rss_mb()
            yield sim, port, good, handler
            good.client.close()
    finally:
        logging.getLogger("eyesim").removeHandler(handler)


class WellBehaved:
    """A program that checks its answers: its PSD sees the same wall, its clock goes on, its
    odometry stays where nothing moved it."""

    def __init__(self, port: int):
        self.client = ProgramClient(port)
        assert self.client.hello(str(GOOD_ROBOT))[1] == GOOD_ROBOT
        x1, _, x2, _ = ROOM
        self.front = self.client.call("PSD_GET", 1)[0]
        # the front sensor sits a little ahead of the robot's centre, half the room from the wall
        assert 0 < self.front < (x2 - x1) / 2, self.front
        self.position = self.client.call("VW_GET_POSITION")
        self.count = self.client.call("OS_GET_COUNT")[0]
        self.calls = 0

    def check(self) -> None:
        assert self.client.call("PSD_GET", 1)[0] == pytest.approx(self.front, abs=2)
        assert self.client.call("VW_GET_POSITION") == self.position
        count = self.client.call("OS_GET_COUNT")[0]
        assert count > self.count
        self.count = count
        self.calls += 3


def fuzz_client(port: int, robot: str | None) -> ProgramClient:
    """A fresh connection, after the handshake for `robot` unless None. The previous fuzzing client
    has just closed; the simulation frees its robot when it reads the close, so retry briefly."""
    deadline = time.monotonic() + 5
    while True:
        client = ProgramClient(port, timeout=REPLY_TIMEOUT)
        if robot is None:
            return client
        try:
            client.hello(robot)
            return client
        except RemoteError as error:
            client.close()
            if error.code != g.ERR_NO_ROBOT or time.monotonic() > deadline:
                raise


def answer_to(client: ProgramClient, request_id: int):
    """The reply or error carrying `request_id` (replies to calls still pending may come first)."""
    while True:
        message = client.receive()
        if message.request_id == request_id:
            return message


@fuzz_settings(EXAMPLES)
@given(st.sampled_from(["1", "3", None]), answered)
def test_fuzzed_requests_are_answered_and_harm_nobody(fuzz_target, robot, request):
    sim, port, good, _ = fuzz_target
    op, request_id, frame = request
    client = fuzz_client(port, robot)
    try:
        client.sock.sendall(frame)
        spec = g.OPS.get(op)
        blocking = spec is not None and spec.blocking and robot is not None
        if not blocking:  # a call that may wait for a key, a timer, a message... is not waited for
            message = answer_to(client, request_id)
            assert message.kind in (g.KIND_REPLY, g.KIND_ERROR)
        # the connection stays open and answers again
        again = client.send("OS_GET_COUNT")
        assert answer_to(client, again).kind in (g.KIND_REPLY, g.KIND_ERROR)
    finally:
        client.close()
    good.check()


EXTREMES = {
    "i32": (0, INT_MAX, INT_MIN),
    "u32": (0, U32_MAX, U32_MAX),
    "f64": (0.0, 1e308, -1e308),
    "str": ("", "\t\n" * 50_000, "\x00é"),
    "bytes": (b"", b"\xff" * 100_000, b"\x00"),
    "i32s": ([], [INT_MAX] * 1000, [INT_MIN]),
}


@pytest.mark.parametrize("code", sorted(g.OPS), ids=lambda code: g.OPS[code].name)
def test_every_operation_with_extreme_values(fuzz_target, code):
    """Not random: each operation surely gets zeros, maxima and minima (camera: its smallest size)."""
    sim, port, good, _ = fuzz_target
    op = g.OPS[code]
    for variant in range(3):
        values = [EXTREMES[typ][variant] for _, typ in op.request]
        if op.name == "CAM_INIT":
            values = [0]
        if op.name == "SIM_SET_ROBOT" and values[0] == 0:
            values[0] = 1
        client = fuzz_client(port, "1")
        try:
            client.sock.sendall(encode_frame(code, g.KIND_REQUEST, 7, encode_payload(op.request, values)))
            if not op.blocking:
                assert answer_to(client, 7).kind in (g.KIND_REPLY, g.KIND_ERROR)
            again = client.send("OS_GET_COUNT")
            assert answer_to(client, again).kind == g.KIND_REPLY
        finally:
            client.close()
    good.check()


@fuzz_settings(EXAMPLES)
@given(st.sampled_from(["1", "3", None]), unanswered)
def test_bytes_that_are_not_whole_frames_harm_nobody(fuzz_target, robot, data):
    sim, port, good, _ = fuzz_target
    client = fuzz_client(port, robot)
    try:
        client.sock.sendall(data)
        length = struct.unpack_from("<I", data)[0] if len(data) >= 4 else None
        if length is not None and not g.HEADER_SIZE <= length <= g.MAX_FRAME:
            message = client.receive()  # a broken length: an error, then the connection closes
            assert message.kind == g.KIND_ERROR and message.request_id == 0
            with pytest.raises((ConnectionError, OSError)):
                while True:
                    client.receive()
    finally:
        client.close()
    good.check()


def test_after_the_fuzzing_the_simulation_steps_and_logged_no_handler_fault(fuzz_target):
    sim, port, good, errors = fuzz_target
    steps = sim.steps
    deadline = time.monotonic() + 5
    while sim.steps <= steps + 10:
        assert time.monotonic() < deadline, "the simulation stopped stepping"
        time.sleep(0.01)
    good.check()
    assert good.calls >= 3 * EXAMPLES  # the well-behaved program was answered after every example
    assert [r.getMessage() for r in errors.records] == []
    assert rss_mb() - good.start_mb < MEMORY_LIMIT_MB  # the simulator runs in this process
