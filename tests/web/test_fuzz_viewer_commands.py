"""Fuzzing the viewer's WebSocket: every browser command type of docs/viewer-channel.md with random
JSON in every field, random extra fields and types, random text and binary frames. Each message
gets no error or one `{"type": "error"}` reply, the connection stays open, the simulation goes on
and nothing logs an error or a traceback.

Derandomized, a few hundred examples: about 10 s. For a longer run set FUZZ_EXAMPLES (e.g. 20000)
and FUZZ_SEED (any integer: a new random series instead of the fixed one)."""

from __future__ import annotations

import asyncio
import json
import logging
import sys
import threading
import time
from pathlib import Path

import aiohttp
import pytest
from hypothesis import given
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.error_log import ErrorLog  # noqa: E402
from support.viewer import viewer_simulation  # noqa: E402
from support.worlds import arena_scene  # noqa: E402
from support.fuzz import examples, fuzz_settings

EXAMPLES = examples(300)
REPLY_TIMEOUT = 10.0


# Fields of each command (docs/viewer-channel.md, "Browser -> server" and "Timeline").
COMMANDS = {
    "key": ("robot", "key"),
    "pause": (),
    "resume": (),
    "speed": ("value",),
    "reset": (),
    "touch": ("robot", "x", "y"),
    "irtv": ("robot", "code"),
    "serial": ("robot", "interface", "text"),
    "digital": ("robot", "line", "level"),
    "analog": ("robot", "channel", "value"),
    "place": ("robot", "object", "x", "y", "phi"),
    "seek": ("time",),
    "live": (),
    "signals": (),
    "series": ("ids",),
    "paths": (),
}
TIMELINE = ("seek", "live", "signals", "series", "paths")  # answered by a task: the answer may come later

scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.sampled_from([0, 1, -1, 2, 4, 8, 16, 20, 21, 319, 479, 1023, 1024, 2**31, 2**53 + 1, 10**308, -(10**308)]),
    st.integers(),
    st.integers(-(10**400), 10**400),  # beyond floats (text frames below go beyond 4300 digits)
    st.floats(allow_nan=False, allow_infinity=False),
    st.sampled_from([1e308, -1e308, 5e-324, 0.01, 1000.0]),
    st.text(max_size=40),
    st.sampled_from(["max", "OK", "RED", "robot/1/x", "robot/1/psd.1", "robot/²/x", "\x00"]),
    st.text(max_size=1).map(lambda t: t * 8_000),
)
json_values = st.recursive(
    scalars,
    lambda inner: st.lists(inner, max_size=5) | st.dictionaries(st.text(max_size=8), inner, max_size=5),
    max_leaves=12,
)


@st.composite
def commands(draw):
    kind = draw(st.sampled_from(sorted(COMMANDS)) | json_values)
    message = {"type": kind}
    for field in COMMANDS.get(kind, ()) if isinstance(kind, str) else ():
        if draw(st.booleans()) or draw(st.booleans()):
            message[field] = draw(json_values)
    message.update(draw(st.dictionaries(st.text(max_size=8), json_values, max_size=2)))
    return json.dumps(message)


MAX_COMMAND_BYTES = 64 * 1024  # a message this large or larger closes the connection, as documented


def _fits(frame) -> bool:
    return len(frame if isinstance(frame, bytes) else frame.encode("utf-8", "surrogatepass")) < MAX_COMMAND_BYTES


frames = st.one_of(
    commands(),
    commands(),
    commands(),
    json_values.map(json.dumps),  # any JSON, not only objects
    st.text(max_size=200),  # any text
    st.sampled_from(
        [
            '{"type": "speed", "value": NaN}',
            '{"type": "seek", "time": Infinity}',
            "[" * 60_000,
            '{"type": "seek", "time": 1' + "0" * 4400 + "}",
            '{"type": "seek", "time": 1e308}',
        ]
    ),
    st.binary(max_size=200),  # a binary frame
).filter(_fits)


class Browser:
    """One WebSocket to the viewer, driven from a loop on a thread of its own, so that every
    example talks over the same connection."""

    def __init__(self, port: int):
        self.loop = asyncio.new_event_loop()
        self.thread = threading.Thread(target=self.loop.run_forever, daemon=True)
        self.thread.start()
        self.sentinels = 0
        self.ws = self.run(self._open(port))

    def run(self, coroutine, timeout=60):
        return asyncio.run_coroutine_threadsafe(coroutine, self.loop).result(timeout)

    async def _open(self, port):
        self.session = aiohttp.ClientSession()
        return await self.session.ws_connect(f"ws://127.0.0.1:{port}/ws", max_msg_size=0)

    async def _exchange(self, frame, timeline: bool) -> list[dict]:
        """Send `frame`, then a command whose error marks the end of the answers to it."""
        if isinstance(frame, bytes):
            await self.ws.send_bytes(frame)
        else:
            await self.ws.send_str(frame)
        self.sentinels += 1
        marker = f"sentinel-{self.sentinels}"
        await self.ws.send_str(json.dumps({"type": marker}))
        errors, sentinel_seen, answered = [], False, not timeline
        while not (sentinel_seen and answered):
            message = await self.ws.receive(timeout=REPLY_TIMEOUT)
            assert message.type == aiohttp.WSMsgType.TEXT, message
            data = json.loads(message.data)
            if data["type"] == "error" and marker in data["message"]:
                sentinel_seen = True
            elif data["type"] == "error":
                errors.append(data)
                answered = True
            elif data["type"] in ("frame", "signals", "series", "paths"):
                answered = True
        return errors

    def exchange(self, frame, timeline: bool = False) -> list[dict]:
        return self.run(self._exchange(frame, timeline))

    def close(self):
        self.run(self.ws.close())
        self.run(self.session.close())
        self.loop.call_soon_threadsafe(self.loop.stop)
        self.thread.join(5)


@pytest.fixture(scope="module")
def viewer_target():
    errors = ErrorLog()
    logging.getLogger().addHandler(errors)
    try:
        scene = arena_scene([("S4", (500, 500, 0)), ("LabBot", (1500, 1500, 90))], objects=[("Can", (1000, 2000, 0))])
        with viewer_simulation(scene) as (sim, _, server):
            browser = Browser(server.port)
            yield sim, browser, errors
            browser.close()
    finally:
        logging.getLogger().removeHandler(errors)


def _is_timeline(frame) -> bool:
    try:
        data = json.loads(frame)
    except (ValueError, TypeError, RecursionError):
        return False
    return isinstance(data, dict) and isinstance(data.get("type"), str) and data["type"] in TIMELINE


@fuzz_settings(EXAMPLES)
@given(frames)
def test_every_command_gets_no_error_or_one_error_and_the_connection_stays(viewer_target, frame):
    sim, browser, _ = viewer_target
    errors = browser.exchange(frame, timeline=_is_timeline(frame))
    assert len(errors) <= 1, errors
    for error in errors:
        assert set(error) == {"type", "message"} and isinstance(error["message"], str)
        assert len(error["message"]) < 2000  # values quoted in errors are shortened
    if isinstance(frame, bytes):
        assert len(errors) == 1
    assert not browser.ws.closed
    # a fuzzed pause, slow speed or look back must not stop the next examples
    for restore in ({"type": "resume"}, {"type": "speed", "value": 1}, {"type": "live"}):
        assert browser.exchange(json.dumps(restore), timeline=restore["type"] == "live") == []


@pytest.mark.parametrize(
    "frame, error",
    [
        ('{"type": [[]]}', "unknown message type [[]]"),  # once a TypeError and a traceback
        ('{"type": "seek", "time": 1e308}', None),  # once an OverflowError in a task: no answer at all
        ('{"type": "seek", "time": 1' + "0" * 400 + "}", None),
        ('{"type": "' + "x" * 30_000 + '"}', "unknown message type 'xxxx"),
    ],
)
def test_what_fuzzing_found(viewer_target, frame, error):
    _, browser, _ = viewer_target
    errors = browser.exchange(frame, timeline="seek" in frame)
    assert [e["message"][: len(error)] for e in errors] == ([error] if error else [])
    assert all(len(e["message"]) < 100 for e in errors)


def test_after_the_fuzzing_the_simulation_steps_and_nothing_logged_an_error(viewer_target):
    sim, browser, errors = viewer_target
    steps = sim.steps
    deadline = time.monotonic() + 5
    while sim.steps <= steps + 10:
        assert time.monotonic() < deadline, "the simulation stopped stepping"
        time.sleep(0.01)
    assert browser.exchange('{"type": "key", "robot": 1, "key": 1}') == []
    assert not browser.ws.closed
    assert [record.getMessage() for record in errors.records] == []
