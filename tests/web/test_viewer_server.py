"""The simulator's viewer server: what a browser gets, bad commands, and slow browsers."""

import asyncio
import base64
import io
import json
import socket
import sys
import time
from pathlib import Path

import aiohttp
import numpy as np
import pytest
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.client import ProgramClient  # noqa: E402
from support.scenes import arena  # noqa: E402
from support.viewer import run_async, viewer_simulation  # noqa: E402


@pytest.fixture
def viewer_sim():
    with viewer_simulation(arena()) as running:
        yield running


async def _collect(url: str, until, send=(), timeout: float = 20.0) -> list[dict]:
    """Messages from the viewer socket until `until(messages)` holds."""
    messages = []
    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(url) as ws:
            for message in send:
                await ws.send_str(json.dumps(message))
            deadline = time.monotonic() + timeout
            while not until(messages):
                remaining = deadline - time.monotonic()
                assert remaining > 0, f"gave up waiting; got types {[m['type'] for m in messages][-20:]}"
                received = await ws.receive(timeout=remaining)
                messages.append(json.loads(received.data))
    return messages


def test_a_browser_gets_the_scene_then_snapshots_and_the_lcd(viewer_sim):
    sim, port, server = viewer_sim
    program = ProgramClient(port)
    program.hello()
    program.call("LCD_PRINTF", "hello viewer")
    program.call("LCD_MENU", "A", "B", "C", "D")
    messages = run_async(
        _collect(
            f"ws://127.0.0.1:{server.port}/ws",
            lambda ms: {"snapshot", "lcd", "menu", "status"} <= {m["type"] for m in ms},
        )
    )
    assert messages[0]["type"] == "scene"
    assert len(messages[0]["walls"]) == 4 and messages[0]["robots"][0]["name"] == "S4"
    menu = next(m for m in messages if m["type"] == "menu")
    assert menu["labels"] == ["A", "B", "C", "D"]
    lcd = next(m for m in messages if m["type"] == "lcd")
    image = Image.open(io.BytesIO(base64.b64decode(lcd["png"])))
    assert image.size == (480, 320)
    assert np.asarray(image.convert("L"))[0:13, 0:100].max() > 200  # the printed text


def test_bad_browser_commands_get_an_error_and_change_nothing(viewer_sim):
    sim, port, server = viewer_sim
    bad = [
        {"type": "key", "robot": 1, "key": 3},
        {"type": "key", "robot": 7, "key": 1},
        {"type": "speed", "value": -1},
        {"type": "warp"},
    ]
    messages = run_async(
        _collect(
            f"ws://127.0.0.1:{server.port}/ws", lambda ms: sum(m["type"] == "error" for m in ms) == len(bad), send=bad
        )
    )
    errors = [m["message"] for m in messages if m["type"] == "error"]
    assert any("key must be one of 1, 2, 4, 8" in e for e in errors) and any("no robot 7" in e for e in errors)
    program = ProgramClient(port)
    program.hello()
    assert program.call("KEY_READ") == (0,)  # no key was pressed by the bad messages


def test_a_browser_that_never_reads_slows_down_nobody(viewer_sim):
    sim, port, server = viewer_sim
    stuck = socket.create_connection(("127.0.0.1", server.port))
    stuck.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    stuck.sendall(
        f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{server.port}\r\n".encode()
        + b"Upgrade: websocket\r\nConnection: Upgrade\r\n"
        b"Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n"
    )
    program = ProgramClient(port)
    program.hello()
    start_time = sim.time

    async def healthy_browser():
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(f"ws://127.0.0.1:{server.port}/ws") as ws:
                lcd_images = 0
                snapshot_time = 0.0
                line = 0
                while lcd_images < 20 or snapshot_time < start_time + 1.0:
                    line += 1
                    program.call("LCD_PRINTF", f"line {line} " + "x" * 40 + "\n")  # a new LCD image each time
                    received = await ws.receive(timeout=10)
                    message = json.loads(received.data)
                    lcd_images += message["type"] == "lcd"
                    if message["type"] == "snapshot":
                        snapshot_time = message["time"]
                return lcd_images, snapshot_time

    lcd_images, snapshot_time = run_async(asyncio.wait_for(healthy_browser(), timeout=60))
    assert lcd_images >= 20 and snapshot_time >= start_time + 1.0
    assert program.call("PSD_GET", 1)[0] > 0
    stuck.close()
