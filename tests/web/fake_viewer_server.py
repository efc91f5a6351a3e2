"""A stand-in for the simulator's web server: serves the built viewer and plays a scripted world."""

from __future__ import annotations

import asyncio
import base64
import io
import json
import math
import socket
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from aiohttp import WSMsgType, web
from PIL import Image, ImageDraw

STATIC_DIR = Path(__file__).resolve().parents[2] / "src" / "eyesim" / "web" / "static"
SNAPSHOT_PERIOD = 1 / 30
STATUS_EVERY = 10  # snapshots

ROBOT_ID = 1
ROBOT_NAME = "S4"
MENU_LABELS = ["Start", "", "Stop", "End"]
CONSOLE_LINES = ["Hello from the fake robot\n", "distance = 123 mm\n"]
LCD_TEXT = "EyeSim LCD"
# Pixels the test LCD image has for certain (x, y) -> (r, g, b).
LCD_MARKS = {(0, 0): (255, 0, 0), (479, 0): (0, 255, 0), (0, 281): (0, 0, 255), (240, 160): (255, 255, 0)}
MENU_BAR_TOP = 320 - 38
WALL_COLOR = [90, 100, 120]

Json = dict[str, Any]


def robot_pose(sim_time: float) -> tuple[list[float], list[float]]:
    """The robot drives anticlockwise around a circle: position and [w, x, y, z] at a time."""
    angle = 0.5 * sim_time
    heading = angle + math.pi / 2
    pos = [1.0 + 0.4 * math.cos(angle), 0.75 + 0.4 * math.sin(angle), 0.0]
    return pos, [math.cos(heading / 2), 0.0, 0.0, math.sin(heading / 2)]


def lcd_png() -> bytes:
    """A 480x320 LCD picture: some text, a rectangle, a menu bar and a few known pixels."""
    image = Image.new("RGB", (480, 320), (0, 0, 0))
    draw = ImageDraw.Draw(image)
    draw.text((20, 20), LCD_TEXT, fill=(255, 255, 255))
    draw.rectangle((200, 120, 280, 200), fill=(30, 144, 255))
    for i, label in enumerate(MENU_LABELS):
        draw.rectangle((i * 120 + 1, MENU_BAR_TOP + 1, i * 120 + 118, 318), fill=(60, 60, 60))
        draw.text((i * 120 + 40, MENU_BAR_TOP + 12), label, fill=(255, 255, 255))
    for xy, rgb in LCD_MARKS.items():
        image.putpixel(xy, rgb)
    buffer = io.BytesIO()
    image.save(buffer, format="PNG")
    return buffer.getvalue()


def floor_texture_png() -> bytes:
    """A chequered floor, 8x6 squares."""
    image = Image.new("RGB", (400, 300), (235, 230, 215))
    draw = ImageDraw.Draw(image)
    for row in range(6):
        for column in range(8):
            if (row + column) % 2:
                draw.rectangle((column * 50, row * 50, column * 50 + 49, row * 50 + 49), fill=(205, 195, 170))
    buffer = io.BytesIO()
    image.save(buffer, format="PNG")
    return buffer.getvalue()


def robot_info(robot_id: int = ROBOT_ID, name: str = ROBOT_NAME) -> Json:
    return {
        "id": robot_id,
        "name": name,
        "type": "S4",
        "size": [0.18, 0.14, 0.09],
        "color": [220, 40, 40],
        "wheel_diameter": 0.06,
        "track": 0.16,
    }


def scene_message(robots: list[Json] | None = None, walls: int = 4, texture: bool = False) -> Json:
    """A 2 m x 1.5 m floor with `walls` walls (the first four enclose it), a can, a ball and a marker."""
    border = [(0, 0, 2, 0), (2, 0, 2, 1.5), (2, 1.5, 0, 1.5), (0, 1.5, 0, 0)]
    inner = [(0.5, 0.5 + 0.1 * i, 0.9, 0.5 + 0.1 * i) for i in range(max(0, walls - 4))]
    return {
        "type": "scene",
        "floor": {"width": 2.0, "height": 1.5, "texture": "/scene/floor-texture" if texture else None},
        "walls": [
            {"x1": x1, "y1": y1, "x2": x2, "y2": y2, "thickness": 0.02, "height": 0.1, "color": WALL_COLOR}
            for x1, y1, x2, y2 in (border + inner)[:walls]
        ],
        "robots": robots if robots is not None else [robot_info()],
        "objects": [
            {"id": 1, "type": "can", "shape": "cylinder", "size": [0.03, 0.12], "color": [240, 200, 0]},
            {"id": 2, "type": "ball", "shape": "sphere", "size": [0.04], "color": [40, 160, 70]},
        ],
        "markers": [{"x": 1.5, "y": 0.3, "color": [0, 90, 255, 200]}],
        "settings": {"vis": False, "trace": False},
    }


class FakeViewerServer:
    """Runs on its own thread and event loop; every browser gets the same world. Use as a context
    manager. `commands` holds what browsers sent (parsed JSON, or the raw text if it was not).
    Set `periodic_status` false to stop the status messages it sends every few snapshots."""

    def __init__(self, static_dir: Path = STATIC_DIR, texture: bool = False) -> None:
        self.static_dir = static_dir
        self.texture = texture
        self.sim_time = 0.0
        self.paused = False
        self.speed: float = 1.0
        self.periodic_status = True
        self.connections = 0
        self.texture_requests = 0
        self.commands: list[Any] = []
        self._changed = threading.Condition()
        self._sockets: set[web.WebSocketResponse] = set()
        self._loop = asyncio.new_event_loop()
        self._thread = threading.Thread(target=self._loop.run_forever, name="fake-viewer-server", daemon=True)
        self._listener = socket.socket()
        self._listener.bind(("127.0.0.1", 0))
        self.url = f"http://127.0.0.1:{self._listener.getsockname()[1]}/"

    def __enter__(self) -> FakeViewerServer:
        self._thread.start()
        self._call(self._start())
        return self

    def __exit__(self, *exc_info: object) -> None:
        self._call(self._stop())
        self._loop.call_soon_threadsafe(self._loop.stop)
        self._thread.join(timeout=5)
        self._loop.close()

    # -- for tests (any thread) --

    def send(self, message: Json | str) -> None:
        """Sends a message (a dict as JSON, a str as it is) to every connected browser."""
        self._call(self._broadcast(message))

    def drop_connections(self) -> None:
        """Closes every WebSocket, as a simulator restart would."""
        self._call(self._close_all())

    def wait_for_command(self, matches: Callable[[Any], bool], timeout: float = 5.0) -> Any:
        """The first command from a browser for which `matches` is true; waits for it."""
        deadline = time.monotonic() + timeout
        with self._changed:
            while True:
                found = next((c for c in self.commands if matches(c)), None)
                if found is not None:
                    return found
                left = deadline - time.monotonic()
                if left <= 0:
                    raise TimeoutError(f"no matching command; received {self.commands!r}")
                self._changed.wait(left)

    def status_message(self) -> Json:
        return {
            "type": "status",
            "time": self.sim_time,
            "paused": self.paused,
            "speed": self.speed,
            "clock": "realtime",
            "real_time_factor": 0.0 if self.paused else self.speed,
        }

    # -- on the server's loop --

    def _call(self, coroutine: Any) -> Any:
        return asyncio.run_coroutine_threadsafe(coroutine, self._loop).result(timeout=10)

    async def _start(self) -> None:
        app = web.Application()
        app.router.add_get("/ws", self._websocket)
        app.router.add_get("/scene/floor-texture", self._floor_texture)
        app.router.add_get("/", self._index)
        app.router.add_static("/", self.static_dir)
        self._runner = web.AppRunner(app)
        await self._runner.setup()
        await web.SockSite(self._runner, self._listener).start()
        self._ticker = asyncio.ensure_future(self._tick())

    async def _stop(self) -> None:
        self._ticker.cancel()
        await self._close_all()
        await self._runner.cleanup()

    async def _index(self, request: web.Request) -> web.FileResponse:
        return web.FileResponse(self.static_dir / "index.html")

    async def _floor_texture(self, request: web.Request) -> web.Response:
        if not self.texture:
            raise web.HTTPNotFound()
        self.texture_requests += 1
        return web.Response(body=floor_texture_png(), content_type="image/png")

    def _snapshot(self) -> Json:
        pos, quat = robot_pose(self.sim_time)
        return {
            "type": "snapshot",
            "time": self.sim_time,
            "robots": [{"id": ROBOT_ID, "pos": pos, "quat": quat}],
            "objects": [
                {"id": 1, "pos": [0.4, 1.1, 0.06], "quat": [1, 0, 0, 0]},
                {"id": 2, "pos": [1.6, 1.2, 0.04], "quat": [1, 0, 0, 0]},
            ],
        }

    async def _greet(self, ws: web.WebSocketResponse) -> None:
        """What a browser gets on connecting: the world, the LCD, the menu, the program so far."""
        await ws.send_json(scene_message(texture=self.texture))
        await ws.send_json(self._snapshot())
        await ws.send_json(self.status_message())
        await ws.send_json({"type": "lcd", "robot": ROBOT_ID, "png": base64.b64encode(lcd_png()).decode()})
        await ws.send_json({"type": "menu", "robot": ROBOT_ID, "labels": MENU_LABELS})
        await ws.send_json(
            {"type": "program", "robot": ROBOT_ID, "event": "started", "name": "demo.py", "exit_code": None}
        )
        for line in CONSOLE_LINES:
            await ws.send_json({"type": "console", "robot": ROBOT_ID, "stream": "stdout", "text": line})

    async def _websocket(self, request: web.Request) -> web.WebSocketResponse:
        ws = web.WebSocketResponse()
        await ws.prepare(request)
        self.connections += 1
        await self._greet(ws)
        self._sockets.add(ws)
        try:
            async for frame in ws:
                if frame.type == WSMsgType.TEXT:
                    await self._obey(frame.data)
        finally:
            self._sockets.discard(ws)
        return ws

    async def _obey(self, text: str) -> None:
        try:
            command = json.loads(text)
        except json.JSONDecodeError:
            command = text
        with self._changed:
            self.commands.append(command)
            self._changed.notify_all()
        kind = command.get("type") if isinstance(command, dict) else None
        if kind in ("pause", "resume"):
            self.paused = kind == "pause"
        elif kind == "speed":
            self.speed = command["value"]
        elif kind == "reset":
            self.sim_time = 0.0
            await self._broadcast(scene_message(texture=self.texture))
        else:
            return
        await self._broadcast(self.status_message())

    async def _tick(self) -> None:
        count = 0
        while True:
            await asyncio.sleep(SNAPSHOT_PERIOD)
            if not self.paused:
                self.sim_time += SNAPSHOT_PERIOD * self.speed
            await self._broadcast(self._snapshot())
            count += 1
            if self.periodic_status and count % STATUS_EVERY == 0:
                await self._broadcast(self.status_message())

    async def _broadcast(self, message: Json | str) -> None:
        text = message if isinstance(message, str) else json.dumps(message)
        for ws in list(self._sockets):
            if not ws.closed:
                await ws.send_str(text)

    async def _close_all(self) -> None:
        for ws in list(self._sockets):
            await ws.close()
