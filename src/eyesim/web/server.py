"""HTTP + WebSocket server for the browser viewer (docs/viewer-channel.md), on the I/O thread.

The simulation hands events and snapshots to the hub on its own thread; the hub moves them to
the I/O loop and on to each browser. Every browser has its own ordered event queue and a single
"latest snapshot" slot, so a slow or closed browser never slows the simulation or other browsers.
LCD images are PNG-encoded off both threads, in a worker."""

from __future__ import annotations

import asyncio
import json
import logging
import math
import secrets
import socket
import time
from collections import deque
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from aiohttp import WSMsgType, web
from PIL import Image

from eyesim.core import inputs
from eyesim.paths import STATIC_DIR
from eyesim.protocol import generated as g
from eyesim.protocol import channel_schema
from eyesim.record.sampling import robot_state
from eyesim.viewer import mesh_message, messages, plain_messages
from eyesim.record import timeline
from eyesim.web.access import AccessPolicy
from eyesim.record.live_history import LiveHistory
from eyesim.web.program_control import ProgramControl
from eyesim.web.program_sources import ProgramSources
from eyesim.web.robot_editor import RobotEditor

log = logging.getLogger("eyesim.web")
CONSOLE_BACKLOG = 500  # console chunks per robot replayed to a browser that connects late
PANEL_CHARACTERS = 50_000  # the viewer's console keeps no more (serial: less): a longer chunk is cut to its end
MAX_COMMAND_BYTES = 64 * 1024  # a browser command is a small JSON object; larger ones close the socket
RECORDER_ONLY = ("input", "edit")  # events for recordings (eyesim/record); browsers see their effects
TEXTURE_TYPES = {"PNG": "image/png", "JPEG": "image/jpeg", "BMP": "image/bmp", "GIF": "image/gif"}


class Browser:
    """One connected browser tab: its ordered events and its latest snapshot."""

    def __init__(self, ws: web.WebSocketResponse):
        self.ws = ws
        self.events: deque = deque()  # (coalesce key or None, str or Future[str])
        self.snapshot: str | None = None
        self.wake = asyncio.Event()
        # Looking back over the history (a `seek`): live snapshots and panel events wait until `live`.
        self.reviewing = False
        self.cursor = timeline.FrameCursor()
        self.timeline_lock = asyncio.Lock()  # one frame at a time: the cursor follows what was sent

    def add_event(self, item, coalesce_key=None) -> None:
        if coalesce_key is not None:
            for index, (key, _) in enumerate(self.events):
                if key == coalesce_key:
                    self.events[index] = (key, item)
                    self.wake.set()
                    return
        self.events.append((coalesce_key, item))
        self.wake.set()

    def set_snapshot(self, text: str) -> None:
        self.snapshot = text
        self.wake.set()

    async def pump(self) -> None:
        while not self.ws.closed:
            await self.wake.wait()
            self.wake.clear()
            while self.events:
                _, item = self.events.popleft()
                # shield: the future is shared with other tabs; closing this one must not cancel it
                text = await asyncio.shield(item) if isinstance(item, asyncio.Future) else item
                await self.ws.send_str(text)
            if self.snapshot is not None:
                text, self.snapshot = self.snapshot, None
                await self.ws.send_str(text)


class ViewerHub:
    """The simulation's listener on the viewer side; lives on the I/O loop."""

    def __init__(self, sim, loop: asyncio.AbstractEventLoop):
        self.sim = sim
        self.loop = loop
        self.browsers: set[Browser] = set()
        self.encoder = ThreadPoolExecutor(max_workers=1, thread_name_prefix="eyesim-png")
        self.lcd: dict[int, asyncio.Future] = {}
        self.cameras: dict[int, asyncio.Future] = {}  # each robot's last camera image
        self.menus: dict[int, str] = {}
        self.programs: dict[int, str] = {}
        self.console: dict[int, deque] = {}
        self.io: dict[int, str] = {}  # each robot's latest I/O state
        self.serial: dict[int, deque] = {}  # recent serial output per robot
        self.latest_snapshot: str | None = None
        self.latest_status: str | None = None
        self._rate = (time.perf_counter(), 0.0, 1.0)  # wall, sim time, real-time factor
        self.history = LiveHistory([r.id for r in sim.robots])
        self._psd_readings: list[tuple] = []  # (robot, time, reading) since the last snapshot; simulation thread
        # In the URLs of the scene's floor texture and models: another scene has other URLs, so a
        # browser never shows the last scene's image from its cache (the routes stay the same).
        self.scene_version = secrets.token_hex(4)

    # -- Listener interface, called on the simulation thread --------------------------------
    @property
    def wants_lcd(self) -> bool:
        return bool(self.browsers)

    def on_event(self, message: dict) -> None:
        self.loop.call_soon_threadsafe(self._event, message, self.sim.time_us)

    def on_snapshot(self, message: dict) -> None:
        states = [robot_state(robot) for robot in self.sim.robots]  # for the history's plots
        readings, self._psd_readings = self._psd_readings, []
        self.loop.call_soon_threadsafe(self._snapshot, message, messages.status(self.sim, None), states, readings)

    def on_request(self, robot, request, reply) -> None:
        """A request observer (engine): PSD readings, for the history's plots. They go to the I/O
        loop with the next snapshot: a hand-over per reading (thousands a second) wrote to that loop's
        wake-up pipe and woke its thread each time."""
        if request.op.code == g.OP_PSD_GET:
            reading = {"robot": robot.id, "psd": request.args[0], "distance_mm": reply[0]}
            self._psd_readings.append((robot.id, request.time_us, reading))

    # -- I/O loop ----------------------------------------------------------------------------
    def _following(self) -> list[Browser]:
        """The browsers showing the present (not looking back over the history)."""
        return [browser for browser in self.browsers if not browser.reviewing]

    def _event(self, message: dict, time_us: int) -> None:
        kind = message["type"]
        if kind in RECORDER_ONLY:
            return
        if kind in ("lcd", "camera"):  # encoded off both threads, only the latest counts
            robot, pixels = message["robot"], message["pixels"]
            future = self.loop.run_in_executor(
                self.encoder, _lcd_message if kind == "lcd" else _camera_message, robot, pixels
            )
            (self.lcd if kind == "lcd" else self.cameras)[robot] = future
            self.history.add_image(robot, kind, time_us, future)
            for browser in self._following():
                browser.add_event(future, coalesce_key=(kind, robot))
            return
        if kind in ("console", "serial") and len(message["text"]) > PANEL_CHARACTERS:
            message = dict(message, text=message["text"][-PANEL_CHARACTERS:])  # 16 MiB once cost 330 MB here
        if kind == "new-scene":  # another scene replaced the running one (scene browser, editor)
            self._forget_scene()
            self.scene_version = secrets.token_hex(4)
            message = self._scene_message(new_scene=True)
            kind = "reset"
            self.sim.call(_publish_io)
        elif kind == "reset":
            message = self._scene_message()
            self.sim.call(_publish_io)
        else:
            self.history.add_event(time_us, message)
        text = json.dumps(message)
        if kind == "menu":
            self.menus[message["robot"]] = text
        elif kind == "program":
            self.programs[message["robot"]] = text
        elif kind == "console":
            self.console.setdefault(message["robot"], deque(maxlen=CONSOLE_BACKLOG)).append(text)
        elif kind == "serial":
            self.serial.setdefault(message["robot"], deque(maxlen=CONSOLE_BACKLOG)).append(text)
        elif kind == "io":  # only the latest state matters
            self.io[message["robot"]] = text
            for browser in self._following():
                browser.add_event(text, coalesce_key=("io", message["robot"]))
            return
        for browser in self.browsers if kind == "reset" else self._following():
            browser.add_event(text)

    def _forget_scene(self) -> None:
        """What the panels showed of the old scene's robots, and its history, go with it."""
        for cache in (self.lcd, self.cameras, self.menus, self.programs, self.console, self.io, self.serial):
            cache.clear()
        self.latest_snapshot = None
        self.history = LiveHistory([r.id for r in self.sim.robots])
        for browser in self.browsers:
            browser.reviewing = False
            browser.cursor = timeline.FrameCursor()

    def _snapshot(self, message: dict, status: dict, states: list[dict], psd_readings: list[tuple]) -> None:
        for robot_id, time_us, reading in psd_readings:
            self.history.add_psd(robot_id, time_us, reading)
        wall, sim_time, rate = self._rate
        now = time.perf_counter()
        if now - wall >= 0.5:
            rate = (status["time"] - sim_time) / (now - wall)
            self._rate = (now, status["time"], rate)
        status["real_time_factor"] = round(rate, 3) if math.isfinite(rate) else None
        self.history.add_snapshot(message, states)
        status["history_start"] = self.history.start_us / 1e6
        text = json.dumps(message)
        status_text = json.dumps(status)
        self.latest_snapshot, self.latest_status = text, status_text
        for browser in self.browsers:
            if not browser.reviewing:
                browser.set_snapshot(text)
            browser.add_event(status_text, coalesce_key=("status",))

    def _scene_message(self, new_scene: bool = False) -> dict:
        texture = self.sim.scene.world.floor_texture
        url = f"/scene/floor-texture?v={self.scene_version}" if texture and Path(texture).is_file() else None
        return messages.scene(self.sim, url, version=self.scene_version, new_scene=new_scene)

    async def attach(self, browser: Browser) -> None:
        browser.add_event(json.dumps(self._scene_message()))
        browser.add_event(json.dumps(plain_messages.timeline("live")))
        self._present(browser)
        first = not self.browsers
        self.browsers.add(browser)
        if first:
            # While no browser watched, LCD images were not published: have every robot's LCD,
            # camera image and I/O state sent again. While one watches they are kept current and
            # a new tab gets them from here (_present): asking again for every tab sent each
            # robot's images to every tab, so 200 tabs opened at once took half a minute.
            self.sim.call(lambda sim: sim.republish_lcd())
            self.sim.call(_publish_io)

    def _present(self, browser: Browser) -> None:
        """Queue what the robot panels and the world show now."""
        if self.latest_snapshot is not None:
            browser.set_snapshot(self.latest_snapshot)
            browser.add_event(self.latest_status, coalesce_key=("status",))
        for robot in self.sim.robots:
            if robot.id in self.menus:
                browser.add_event(self.menus[robot.id])
            if robot.id in self.programs:
                browser.add_event(self.programs[robot.id])
            for chunk in self.console.get(robot.id, ()):
                browser.add_event(chunk)
            for chunk in self.serial.get(robot.id, ()):
                browser.add_event(chunk)
            if robot.id in self.io:
                browser.add_event(self.io[robot.id], coalesce_key=("io", robot.id))
            if robot.id in self.lcd:
                browser.add_event(self.lcd[robot.id], coalesce_key=("lcd", robot.id))
            if robot.id in self.cameras:
                browser.add_event(self.cameras[robot.id], coalesce_key=("camera", robot.id))

    async def timeline_command(self, browser: Browser, message: dict) -> None:
        """`seek`, `signals`, `series`, `paths` over the history, and `live` to follow the present again."""
        async with browser.timeline_lock:
            if message["type"] == "live":
                browser.reviewing = False
                browser.cursor = timeline.FrameCursor()
                browser.add_event(plain_messages.frame_text(self.sim.time, self.history.robot_ids, []))
                self._present(browser)
                return
            if message["type"] == "seek":
                browser.reviewing = True
            try:
                reply = await timeline.answer(self.history, browser.cursor, message)
            except ValueError as error:
                reply = json.dumps(plain_messages.error(str(error)))
            except Exception:  # a bad value the checks missed: this browser gets an error, nobody else notices
                log.exception("viewer command %.200r failed", message)
                reply = json.dumps(
                    plain_messages.error(f"{message['type']}: the simulator could not carry out this command")
                )
            browser.add_event(reply)

    def detach(self, browser: Browser) -> None:
        self.browsers.discard(browser)

    def resend_scene(self) -> None:
        """The scene's description changed (its settings): every browser gets it afresh. Any thread."""
        self.loop.call_soon_threadsafe(self._event, {"type": "reset"}, self.sim.time_us)

    # -- commands from a browser -------------------------------------------------------------
    def command(self, message: dict) -> str | None:
        """Queue a browser command (already checked against the schema) for the simulation;
        return an error text for one the simulation state refuses."""
        kind = message["type"]
        if kind in inputs.INPUTS:
            try:
                self.sim.call(inputs.prepare(self.sim, message, checked=True))
            except inputs.InputError as error:
                return str(error)
        elif kind in ("pause", "resume"):
            self.sim.call(lambda sim: sim.clock.set_paused(kind == "pause", sim.time_us))
        elif kind == "speed":
            value = math.inf if message["value"] == "max" else float(message["value"])
            self.sim.call(lambda sim: sim.clock.set_speed(value, sim.time_us))
        elif kind == "reset":
            self.sim.call(lambda sim: sim.reset())
        elif kind == "step":  # running: it pauses after the step
            duration_us = round(message.get("seconds", 0) * 1e6)
            self.sim.call(lambda sim: sim.step_for(duration_us))
        else:  # in the schema but not handled here: say so in the log (see command_text)
            raise NotImplementedError(f"no handler for the viewer command {kind!r}")
        return None

    def command_text(self, text: str, browser: Browser) -> str | None:
        """A command as the browser sent it: the error text for a bad one, else None."""
        try:
            data = json.loads(text, parse_constant=_reject_constant)
        except (ValueError, RecursionError) as error:
            return f"not valid JSON: {error}"
        problem = channel_schema.command_problem(data)
        if problem:
            return problem
        if data["type"] in timeline.TIMELINE_COMMANDS + ("live",):
            self.loop.create_task(self.timeline_command(browser, data))
            return None
        try:
            return self.command(data)
        except Exception:  # a bad value the checks missed: this browser gets an error, nobody else notices
            log.exception("viewer command %.200r failed", text)
            return f"{data.get('type')!r}: the simulator could not carry out this command"


def _reject_constant(name: str):
    raise ValueError(f"{name} is not a number here")


def _image_type(path: Path) -> str | None:
    """The Content-Type of an image file we are willing to serve, else None."""
    try:
        if path.is_symlink() and path.parent.resolve() not in path.resolve().parents:
            return None  # a link out of its folder
        with Image.open(path) as image:
            return TEXTURE_TYPES.get(image.format)
    except (OSError, ValueError):
        return None


def _publish_io(sim) -> None:
    for robot in sim.robots:
        sim.events.io(robot)


def _lcd_message(robot: int, pixels) -> str:
    return json.dumps(plain_messages.lcd(robot, pixels))


def _camera_message(robot: int, pixels) -> str:
    return json.dumps(plain_messages.camera(robot, pixels))


async def serve_app(app: web.Application, host: str, port: int) -> tuple[web.AppRunner, int]:
    """Serve `app` on host:port (0: any free port); returns its runner and the port it got."""
    runner = web.AppRunner(app, access_log=None)
    await runner.setup()
    site = web.TCPSite(runner, host, port)
    await site.start()
    server = site._server
    if not isinstance(server, asyncio.Server):
        raise RuntimeError(f"the viewer could not listen on {host}:{port}")
    return runner, server.sockets[0].getsockname()[1]


def viewer_url(host: str, port: int, access: AccessPolicy) -> str:
    """The URL to print for the page (with the access token when one is needed)."""
    host = socket.gethostname() if host in ("0.0.0.0", "::", "") else host
    host = f"[{host}]" if ":" in host else host
    return f"http://{host}:{port}/{access.url_suffix()}"


async def static_file(request: web.Request) -> web.StreamResponse:
    """The viewer's built page and assets (the live viewer's and the replay's)."""
    relative = request.match_info["path"] or "index.html"
    root = STATIC_DIR.resolve()
    path = (root / relative).resolve()
    if root not in path.parents and path != root:
        raise web.HTTPNotFound()
    if not path.is_file():
        if relative == "index.html":
            return web.Response(
                status=500,
                text="The viewer assets are missing from this install: run `make viewer` in the EyeSim source tree.",
            )
        raise web.HTTPNotFound()
    # Bundle file names are fixed: make browsers revalidate so an upgrade shows at once.
    return web.FileResponse(path, headers={"Cache-Control": "no-cache"})


class ViewerServer:
    def __init__(
        self,
        sim,
        io_thread,
        host: str = "127.0.0.1",
        port: int = 8080,
        token: str | None = None,
        launcher=None,
        run_folder: Path | None = None,
        require_token: bool = True,
    ):
        """`launcher` runs the programs the page starts (none: the page cannot start programs);
        `run_folder` is the first scene root (default: the current folder)."""
        self.sim = sim
        self.launcher = launcher
        self.run_folder = run_folder or Path.cwd()
        self.io = io_thread
        self.host = host
        self.port = port
        self.access = AccessPolicy(host, token, require_token)
        self.hub: ViewerHub | None = None
        # robot files the editor opens and saves stay under the folder the simulator started in
        self.robot_editor = RobotEditor(self.run_folder)
        self.workspace = None  # the scene browser and editor (scene_workspace.py), set before start
        self._runner: web.AppRunner | None = None

    @property
    def url(self) -> str:
        return viewer_url(self.host, self.port, self.access)

    def start(self) -> None:
        hub = self.io.run(self._start())
        self.sim.events.subscribe(hub)
        self.sim.call(lambda sim: sim.request_observers.append(hub.on_request))

    async def _start(self) -> ViewerHub:
        """Serve the page; returns the hub it made (on the I/O loop, which the hub lives on)."""
        hub = self.hub = ViewerHub(self.sim, asyncio.get_running_loop())
        app = web.Application(middlewares=[self.access.middleware])
        app.router.add_get("/ws", self._websocket)
        app.router.add_get("/scene/floor-texture", self._floor_texture)
        app.router.add_get("/scene/mesh/{kind}/{id}", self._mesh)
        if self.launcher is not None:
            programs = ProgramControl(self.sim, self.launcher, self.run_folder, hub.resend_scene)
            programs.add_routes(app.router)
            ProgramSources(programs).add_routes(app.router)
        self.robot_editor.add_routes(app)
        if self.workspace is not None:
            self.workspace.add_routes(app)
        app.router.add_get("/{path:.*}", static_file)
        self._runner, self.port = await serve_app(app, self.host, self.port)
        return hub

    def stop(self) -> None:
        if self.hub is not None and self.hub in self.sim.events.listeners:
            self.sim.events.unsubscribe(self.hub)
        if self.hub is not None and self.hub.on_request in self.sim.request_observers:
            self.sim.request_observers.remove(self.hub.on_request)
        if self._runner is not None:
            self.io.run(self._runner.cleanup())

    async def _floor_texture(self, request: web.Request) -> web.StreamResponse:
        """Only the image the scene names, and only if it is an image: a scene file is not allowed
        to turn this route into a way of reading other files."""
        texture = self.sim.scene.world.floor_texture
        content_type = _image_type(Path(texture)) if texture else None
        if content_type is None:
            raise web.HTTPNotFound()
        # The URL names the scene (?v=): the browser may keep it, but asks whether it changed.
        return web.FileResponse(texture, headers={"Content-Type": content_type, "Cache-Control": "no-cache"})

    async def _mesh(self, request: web.Request) -> web.StreamResponse:
        """A robot's or object's .obj model as JSON triangles (mesh_message.py); 404 without one."""
        kind, number = request.match_info["kind"], request.match_info["id"]
        valid = number.isascii() and number.isdigit() and len(number) <= 9
        body = mesh_message.body_of(self.sim, kind, int(number)) if valid else None
        if body is None or not mesh_message.has_mesh(self.sim, body):
            raise web.HTTPNotFound()
        # a big model takes a moment to turn into JSON: not on the I/O loop
        text = await asyncio.get_running_loop().run_in_executor(
            None, lambda: json.dumps(mesh_message.mesh_message(self.sim.world.model, body))
        )
        return web.Response(text=text, content_type="application/json")

    async def _websocket(self, request: web.Request) -> web.WebSocketResponse:
        ws = web.WebSocketResponse(heartbeat=20, max_msg_size=MAX_COMMAND_BYTES)
        await ws.prepare(request)
        browser = Browser(ws)
        hub = self.hub
        assert hub is not None, "the WebSocket route is served only once _start made the hub"
        await hub.attach(browser)
        pump = asyncio.get_running_loop().create_task(browser.pump())
        try:
            async for message in ws:
                if message.type == WSMsgType.TEXT:
                    error = hub.command_text(message.data, browser)
                elif message.type == WSMsgType.BINARY:
                    error = "binary messages are not understood: send JSON text"
                else:
                    continue
                if error:
                    browser.add_event(json.dumps(plain_messages.error(error)))
        finally:
            hub.detach(browser)
            pump.cancel()
        return ws
