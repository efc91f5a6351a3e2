"""The viewer channel's limits (docs/viewer-channel.md): a command of 64 KiB or more closes the
connection (1009), anything smaller is answered and the connection stays; a console chunk over
50,000 characters arrives as its last 50,000; a browser that connects late gets the last 500
chunks per robot; the live history keeps 2000 chunks per robot and a frame carries 500."""

from __future__ import annotations

import json

import aiohttp
import pytest
from support.client import ProgramClient
from support.scenes import arena
from support.viewer import run_async, viewer_simulation

from eyesim.record.live_history import MAX_CHUNKS, LiveHistory
from eyesim.web.server import CONSOLE_BACKLOG, MAX_COMMAND_BYTES, PANEL_CHARACTERS
from eyesim.record.timeline import STREAM_BACKLOG


@pytest.fixture
def viewer_sim():
    with viewer_simulation(arena(robots=((500, 500, 0), (1500, 1500, 90)))) as running:
        yield running


def test_the_limits_are_the_documented_ones():
    assert (MAX_COMMAND_BYTES, PANEL_CHARACTERS, CONSOLE_BACKLOG, MAX_CHUNKS, STREAM_BACKLOG) == (
        64 * 1024,
        50_000,
        500,
        2000,
        500,
    )


async def _errors_until_sentinel(ws) -> list[str]:
    await ws.send_str(json.dumps({"type": "sentinel"}))
    errors = []
    while True:
        message = json.loads((await ws.receive(timeout=10)).data)
        if message["type"] == "error":
            if message["message"] == "unknown message type 'sentinel'":
                return errors
            errors.append(message["message"])


def test_a_command_up_to_the_size_limit_is_answered_and_one_over_it_closes_the_connection(viewer_sim):
    sim, port, server = viewer_sim
    program = ProgramClient(port)
    program.hello("1")
    program.call("SER_INIT", 1, 115200, 0)
    longest_text = {"type": "serial", "robot": 1, "interface": 1, "text": "a" * 50_000}
    too_long_text = dict(longest_text, text="a" * 50_001)
    padding = MAX_COMMAND_BYTES - 1 - len(json.dumps({"type": "pause", "x": ""}))
    just_fits = json.dumps({"type": "pause", "x": "p" * padding})  # one byte under 64 KiB: answered
    assert len(just_fits) == MAX_COMMAND_BYTES - 1

    async def talk():
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(f"ws://127.0.0.1:{server.port}/ws", max_msg_size=0) as ws:
                for command in (longest_text, too_long_text):
                    await ws.send_str(json.dumps(command))
                await ws.send_str(just_fits)
                await ws.send_bytes(b"\x00" * 1000)
                errors = await _errors_until_sentinel(ws)
                await ws.send_str(just_fits + " ")  # 64 KiB: too big
                while (message := await ws.receive(timeout=10)).type == aiohttp.WSMsgType.TEXT:
                    pass
                return errors, message.type, ws.close_code

    errors, last, close_code = run_async(talk())
    assert errors == [
        "serial: text must have at most 50000 characters",
        "pause: unknown field 'x' (fields: type)",
        "binary messages are not understood: send JSON text",
    ]
    assert last in (aiohttp.WSMsgType.CLOSE, aiohttp.WSMsgType.CLOSED, aiohttp.WSMsgType.CLOSING)
    assert close_code == 1009  # message too big
    assert program.call("SER_RECEIVE", 1, 100_000)[0] == b"a" * 50_000  # the longest text arrived whole


def test_long_console_chunks_are_cut_and_late_browsers_get_the_last_500(viewer_sim):
    sim, port, server = viewer_sim
    url = f"ws://127.0.0.1:{server.port}/ws"
    sim.call(lambda s: s.events.console(1, "stdout", "x" * 40_000 + "y" * 60_000))
    for chunk in range(CONSOLE_BACKLOG + 100):
        sim.call(lambda s, c=chunk: s.events.console(2, "stdout", f"line {c}\n"))

    async def consoles(until) -> list[dict]:
        got = []
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(url, max_msg_size=0) as ws:
                while not until(got):
                    message = json.loads((await ws.receive(timeout=10)).data)
                    if message["type"] == "console":
                        got.append(message)
        return got

    # the first browser waits for the last chunk; one that connects afterwards gets the backlog
    run_async(consoles(lambda got: any(m["text"] == f"line {CONSOLE_BACKLOG + 99}\n" for m in got)))
    late = run_async(consoles(lambda got: len(got) >= 1 + CONSOLE_BACKLOG))
    first = [m["text"] for m in late if m["robot"] == 1]
    assert first == ["y" * PANEL_CHARACTERS]  # the chunk's last 50,000 characters
    second = [m["text"] for m in late if m["robot"] == 2]
    assert second == [f"line {c}\n" for c in range(100, CONSOLE_BACKLOG + 100)]


def test_the_live_history_keeps_2000_chunks_per_robot_and_a_frame_carries_500():
    from eyesim.record.timeline import FrameCursor

    history = LiveHistory([1])
    history.add_snapshot({"type": "snapshot", "time": 0.0, "robots": [], "objects": [], "bodies": []}, [])
    for chunk in range(MAX_CHUNKS + 300):
        history.add_event(1000 + chunk, {"type": "console", "robot": 1, "stream": "stdout", "text": f"{chunk}\n"})
    history.add_snapshot({"type": "snapshot", "time": 1.0, "robots": [], "objects": [], "bodies": []}, [])
    kept = history.events.stream("console", 1, -1, 10**9)
    assert [m["text"] for m in kept] == [f"{c}\n" for c in range(300, MAX_CHUNKS + 300)]
    frame = json.loads(run_async(FrameCursor().frame(history, 1_000_000)))
    texts = [m["text"] for m in frame["messages"] if m["type"] == "console"]
    assert texts == [f"{c}\n" for c in range(MAX_CHUNKS + 300 - STREAM_BACKLOG, MAX_CHUNKS + 300)]


async def _tabs_receiving(port: int, tabs: int, seconds: float) -> list[dict]:
    """Open `tabs` viewer connections 0.1 s apart, read each for `seconds`; count LCD images per robot."""
    import asyncio
    import time

    async def tab(session):
        counts: dict = {}
        async with session.ws_connect(f"ws://127.0.0.1:{port}/ws", max_msg_size=0) as ws:
            end = time.monotonic() + seconds
            while time.monotonic() < end:
                try:
                    message = await ws.receive(timeout=max(0.01, end - time.monotonic()))
                except asyncio.TimeoutError:
                    break
                if message.type == aiohttp.WSMsgType.TEXT and '"type": "lcd"' in message.data[:40]:
                    robot = json.loads(message.data)["robot"]
                    counts[robot] = counts.get(robot, 0) + 1
        return counts

    async def later(session, delay):
        await asyncio.sleep(delay)
        return await tab(session)

    async with aiohttp.ClientSession(connector=aiohttp.TCPConnector(limit=0)) as session:
        return await asyncio.gather(*(later(session, 0.1 * i) for i in range(tabs)))


def test_tabs_opened_one_after_another_each_get_every_lcd_once():
    """A new tab gets the robots' LCD images the others keep current; it does not make the
    simulator send every robot's image to every tab again (200 tabs once took half a minute)."""

    class Published:
        wants_lcd = False
        images = 0

        def on_event(self, message):
            self.images += message["type"] == "lcd"

        def on_snapshot(self, message):
            pass

    robots = tuple((300 + 300 * i, 500, 0) for i in range(6))
    published = Published()
    with viewer_simulation(arena(robots=robots, size=2500)) as (sim, _, server):
        sim.call(lambda sim: sim.events.subscribe(published))
        counts = run_async(_tabs_receiving(server.port, 20, 2.5))
    for tab in counts:
        assert sorted(tab) == [1, 2, 3, 4, 5, 6]  # every robot's LCD, though no program draws on one
        assert max(tab.values()) <= 2, tab  # the images do not change: sent once (twice in a race)
    assert published.images == 6  # made and encoded once for all 20 tabs, not once per tab
