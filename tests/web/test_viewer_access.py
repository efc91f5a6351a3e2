"""The viewer serves only its own page: foreign origins and host names are refused, a server wants
its token (on loopback too, unless started without one), file routes serve only the scene's images, and a closing
tab or a malformed command affects nobody else."""

import asyncio
import dataclasses
import json
import os
import sys
import time
from pathlib import Path

import aiohttp
import pytest
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.client import ProgramClient  # noqa: E402
from support.scenes import arena  # noqa: E402
from support.simulator import running_simulation  # noqa: E402
from support.viewer import run_async, viewer_simulation  # noqa: E402

from eyesim.web.io_thread import IoThread  # noqa: E402
from eyesim.web.access import AccessPolicy, is_loopback  # noqa: E402
from eyesim.web.server import ViewerServer  # noqa: E402


@pytest.fixture
def viewer_sim():
    with viewer_simulation(arena()) as running:
        yield running


async def _status(url: str, headers=None, cookies=None) -> int:
    async with aiohttp.ClientSession(cookies=cookies) as session:
        async with session.get(url, headers=headers or {}) as response:
            return response.status


async def _ws_status(url: str, headers=None) -> int:
    """101 when the WebSocket opened, else the HTTP status it was refused with."""
    async with aiohttp.ClientSession() as session:
        try:
            async with session.ws_connect(url, headers=headers or {}):
                return 101
        except aiohttp.WSServerHandshakeError as error:
            return error.status


def test_the_own_page_and_its_websocket_are_served(viewer_sim):
    _, _, server = viewer_sim
    base = f"127.0.0.1:{server.port}"
    assert run_async(_status(f"http://{base}/")) == 200
    assert run_async(_ws_status(f"ws://{base}/ws", {"Origin": f"http://{base}"})) == 101
    assert run_async(_status(f"http://localhost:{server.port}/")) == 200


def test_a_foreign_origin_is_refused(viewer_sim):
    _, _, server = viewer_sim
    base = f"127.0.0.1:{server.port}"
    assert run_async(_ws_status(f"ws://{base}/ws", {"Origin": "https://evil.example"})) == 403
    assert run_async(_ws_status(f"ws://{base}/ws", {"Origin": f"http://localhost:{server.port}"})) == 403
    assert run_async(_status(f"http://{base}/", {"Origin": "https://evil.example"})) == 403


def test_an_unknown_host_name_is_refused(viewer_sim):
    """DNS rebinding: another site's name made to resolve to 127.0.0.1 keeps its own Host."""
    _, _, server = viewer_sim
    base = f"127.0.0.1:{server.port}"
    evil = {"Host": f"evil.example:{server.port}"}
    assert run_async(_status(f"http://{base}/", evil)) == 403
    assert run_async(_status(f"http://{base}/scene/floor-texture", evil)) == 403
    assert run_async(_ws_status(f"ws://{base}/ws", {**evil, "Origin": f"http://evil.example:{server.port}"})) == 403


def test_host_and_origin_rules():
    policy = AccessPolicy("127.0.0.1")  # a token on loopback too: every local user reaches the port
    assert policy.token and policy.url_suffix() == f"?token={policy.token}"
    assert AccessPolicy("127.0.0.1", require_token=False).token is None
    with pytest.raises(ValueError, match="may only listen on loopback"):
        AccessPolicy("0.0.0.0", require_token=False)
    assert is_loopback("localhost") and is_loopback("127.0.0.5") and is_loopback("[::1]")
    assert not is_loopback("0.0.0.0") and not is_loopback("192.168.1.4") and not is_loopback("evil.example")
    remote = AccessPolicy("0.0.0.0")
    assert remote.token and len(remote.token) >= 20 and remote.url_suffix() == f"?token={remote.token}"
    assert AccessPolicy("0.0.0.0").token != remote.token  # random each start


def test_a_server_on_all_addresses_wants_its_token(caplog):
    with running_simulation(arena()) as (sim, _):
        io = IoThread()
        io.start()
        server = ViewerServer(sim, io, "0.0.0.0", 0)
        server.start()
        try:
            token = server.access.token
            assert server.url.endswith(f"/?token={token}")
            base = f"http://127.0.0.1:{server.port}"

            async def visit():
                refused = await _status(f"{base}/")
                wrong = await _status(f"{base}/?token=guess")
                # browsers keep cookies of IP-address hosts; aiohttp only with unsafe=True
                async with aiohttp.ClientSession(cookie_jar=aiohttp.CookieJar(unsafe=True)) as session:
                    async with session.get(f"{base}/?token={token}") as response:
                        first = response.status
                    async with session.get(f"{base}/index.html") as response:  # the cookie now
                        later = response.status
                    async with session.ws_connect(f"ws://127.0.0.1:{server.port}/ws") as ws:
                        scene = json.loads((await ws.receive(timeout=10)).data)
                return refused, wrong, first, later, scene["type"]

            with caplog.at_level("WARNING", logger="eyesim.web"):
                assert run_async(visit()) == (403, 403, 200, 200, "scene")
            assert "access token" in caplog.text
        finally:
            server.stop()
            io.stop()


def _texture_scene(tmp_path: Path, texture: Path):
    scene = arena()
    return dataclasses.replace(scene, world=dataclasses.replace(scene.world, floor_texture=str(texture)))


async def _get(url: str):
    async with aiohttp.ClientSession() as session:
        async with session.get(url) as response:
            return response.status, response.headers.get("Content-Type"), await response.read()


def test_the_floor_texture_route_serves_only_an_image(tmp_path):
    image = tmp_path / "floor.bmp"
    Image.new("RGB", (8, 8), (0, 200, 0)).save(image)
    secret = tmp_path / "secret.txt"
    secret.write_text("password")
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    Image.new("RGB", (8, 8)).save(outside / "other.png")
    scenes = tmp_path / "scene"
    scenes.mkdir()
    os.symlink(secret, scenes / "text.png")
    os.symlink(outside / "other.png", scenes / "linked.png")
    expected = {
        image: (200, "image/bmp"),
        secret: (404, None),
        scenes / "text.png": (404, None),
        scenes / "linked.png": (404, None),
    }
    for texture, (status, content_type) in expected.items():
        with viewer_simulation(_texture_scene(tmp_path, texture)) as (_, _, server):
            got_status, got_type, body = run_async(_get(f"http://127.0.0.1:{server.port}/scene/floor-texture"))
            assert got_status == status, texture
            if status == 200:
                assert got_type == content_type and body == image.read_bytes()
            else:
                assert b"password" not in body


def test_mesh_route_with_odd_ids_is_a_plain_404(viewer_sim):
    _, _, server = viewer_sim
    for ident in ("%C2%B2", "9" * 5000, "-1", "1.5"):
        status, _, _ = run_async(_get(f"http://127.0.0.1:{server.port}/scene/mesh/robot/{ident}"))
        assert status == 404, ident


def test_malformed_commands_get_an_error_and_the_socket_stays_open(viewer_sim):
    sim, port, server = viewer_sim
    bad_texts = [
        '{"type": "speed", "value": Infinity}',
        '{"type": "speed", "value": NaN}',
        '{"type": "speed", "value": 1e-300}',
        '{"type": "place", "robot": 1, "x": ' + "9" * 400 + ', "y": 1, "phi": 0}',
        '{"type": "key", "robot": 1, "key": [1]}',
        '{"type": "key", "robot": true, "key": 1}',
        "[" * 20000 + "]" * 20000,
        '{"type": "key", "robot": ' + "1" * 5000 + ', "key": 1}',
        '"just a string"',
    ]

    async def talk():
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(f"ws://127.0.0.1:{server.port}/ws", max_msg_size=0) as ws:
                for text in bad_texts[:-3]:
                    await ws.send_str(text)
                await ws.send_bytes(b"\x00\x01binary")
                errors = []
                while len(errors) < len(bad_texts) - 2:
                    message = json.loads((await ws.receive(timeout=10)).data)
                    if message["type"] == "error":
                        errors.append(message["message"])
                for text in bad_texts[-3:]:
                    await ws.send_str(text)
                while len(errors) < len(bad_texts) + 1:
                    message = json.loads((await ws.receive(timeout=10)).data)
                    if message["type"] == "error":
                        errors.append(message["message"])
                await ws.send_str(json.dumps({"type": "key", "robot": 1, "key": 1}))  # still listened to
                await ws.send_str(json.dumps({"type": "no such command"}))  # answered once the key is taken
                while True:
                    message = json.loads((await ws.receive(timeout=10)).data)
                    if message["type"] == "error":
                        return errors, ws.closed

    errors, closed = run_async(talk())
    assert not closed
    assert all(len(e) < 300 for e in errors), errors
    assert sum("not valid JSON" in e for e in errors) >= 4  # Infinity, NaN, deep nesting, 5000 digits
    assert any("0.01" in e for e in errors) and any("binary" in e for e in errors)
    assert any("place" in e and "off the floor" in e for e in errors)
    program = ProgramClient(port)
    program.hello()
    assert program.call("KEY_READ") == (1,)  # only the good key press arrived
    assert sim.clock.speed == 1.0


def test_closing_tabs_never_freezes_another(viewer_sim):
    """A program animates its LCD every 10 ms while tabs open and close 60 times; a tab that stayed
    open and one opened at the end both keep getting new LCD images and snapshots."""
    sim, port, server = viewer_sim
    url = f"ws://127.0.0.1:{server.port}/ws"
    program = ProgramClient(port)
    program.hello()
    stop = asyncio.Event()

    async def animate():
        line = 0
        while not stop.is_set():
            line += 1
            await asyncio.to_thread(program.call, "LCD_SET_PRINTF", 0, 0, f"frame {line:06d}")
            await asyncio.sleep(0.01)

    async def fresh_lcd(ws, count: int) -> int:
        seen = 0
        deadline = time.monotonic() + 15
        while seen < count:
            message = json.loads((await ws.receive(timeout=max(0.1, deadline - time.monotonic()))).data)
            seen += message["type"] == "lcd"
        return seen

    async def scenario():
        animation = asyncio.create_task(animate())
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(url) as steady:
                await fresh_lcd(steady, 1)
                for _ in range(60):
                    async with session.ws_connect(url) as tab:
                        await tab.receive(timeout=10)
                        await asyncio.sleep(0.005)
                steady_after = await fresh_lcd(steady, 5)
                async with session.ws_connect(url) as last:
                    last_after = await fresh_lcd(last, 5)
        stop.set()
        await animation
        return steady_after, last_after

    assert run_async(asyncio.wait_for(scenario(), timeout=120)) == (5, 5)


def test_a_loopback_server_wants_its_token_too():
    """Any user of a shared lab machine can connect to a loopback port: without the token from the
    printed URL, nothing is served (page, assets or WebSocket)."""
    with running_simulation(arena()) as (sim, _):
        io = IoThread()
        io.start()
        server = ViewerServer(sim, io, "127.0.0.1", 0)
        server.start()
        try:
            token = server.access.token
            base = f"127.0.0.1:{server.port}"
            assert server.url == f"http://{base}/?token={token}"
            assert run_async(_status(f"http://{base}/")) == 403
            assert run_async(_status(f"http://{base}/index.html")) == 403
            assert run_async(_ws_status(f"ws://{base}/ws", {"Origin": f"http://{base}"})) == 403
            assert run_async(_status(f"http://{base}/?token={token}")) == 200
            assert run_async(_status(f"http://{base}/index.html", cookies={"eyesim_token": token})) == 200
        finally:
            server.stop()
            io.stop()
