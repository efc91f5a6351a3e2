"""`eyesim replay`: the viewer page over a recording instead of a live simulation.

The browser gets the recorded `scene`, a `timeline` message saying this is a replay, and then a
`frame` for every time it asks for (`seek`); plots ask for `signals` and `series`, the paths for
`paths` (docs/viewer-channel.md). The floor texture and .obj models come from the recording's
attachments. Commands that would change a live run get an error. The page may send another
recording (`POST /recording`): every open page then shows that one.

Over a grading report (`eyesim replay REPORT_FOLDER`, `eyesim grade --serve`) it also serves the
report at /report/, whose "Watch the run" links (`/replay-case?file=cases/...`) show that case's
recording and open the viewer on it."""

from __future__ import annotations

import asyncio
import json
import logging
import reprlib
import secrets
import shutil
import sys
import tempfile
from pathlib import Path

from aiohttp import WSMsgType, web

from eyesim.paths import CASE_RECORDING as RECORDING
from eyesim.protocol import channel_schema
from eyesim.record.recording import Recording, RecordingError
from eyesim.viewer import plain_messages
from eyesim.record import timeline
from eyesim.web.access import AccessPolicy
from eyesim.web.server import MAX_COMMAND_BYTES, TEXTURE_TYPES, _reject_constant, serve_app, static_file, viewer_url

log = logging.getLogger("eyesim.web")
MAX_UPLOAD_BYTES = 4 * 1024**3  # a recording sent from the page (hours of cameras are a few GB)


class ReplayServer:
    def __init__(
        self,
        recording,
        host: str = "127.0.0.1",
        port: int = 8080,
        token: str | None = None,
        report_dir: Path | None = None,
        require_token: bool = True,
    ):
        self.recording = recording
        self.report_dir = None if report_dir is None else Path(report_dir).resolve()
        self.source = timeline.RecordingTimeline(recording, secrets.token_hex(4))
        self.host = host
        self.port = port
        self.access = AccessPolicy(host, token, require_token)
        self._runner: web.AppRunner | None = None
        self._pages: dict[web.WebSocketResponse, timeline.FrameCursor] = {}
        # Made at the first upload: a server ended without its cleanup (a closed console window on
        # Windows, a terminal's hangup) then leaves no empty folder behind.
        self._uploads: tempfile.TemporaryDirectory | None = None
        self._uploaded = 0
        self._owned = False  # the recording shown was opened here (an upload or a report's case), not given

    @property
    def url(self) -> str:
        return viewer_url(self.host, self.port, self.access)

    async def start(self) -> None:
        app = web.Application(middlewares=[self.access.middleware], client_max_size=MAX_UPLOAD_BYTES)
        app.router.add_get("/ws", self._websocket)
        app.router.add_post("/recording", self._open)
        app.router.add_get("/scene/floor-texture", self._floor_texture)
        app.router.add_get("/scene/mesh/{kind}/{id}", self._mesh)
        if self.report_dir is not None:
            app.router.add_get("/report/{path:.*}", self._report_file)
            app.router.add_get("/replay-case", self._replay_case)
        app.router.add_get("/{path:.*}", static_file)
        self._runner, self.port = await serve_app(app, self.host, self.port)

    async def stop(self) -> None:
        if self._runner is not None:
            await self._runner.cleanup()
        if self._owned:
            self.recording.close()
        if self._uploads is not None:
            self._uploads.cleanup()

    @property
    def report_url(self) -> str:
        return self.url.replace("/?", "/report/?") if "?" in self.url else self.url + "report/"

    async def _open(self, request: web.Request) -> web.Response:
        """Another recording, sent by the page: checked, then shown on every open page. Only the one
        shown is kept: a rejected upload, and the one it replaces, are deleted at once."""
        name = Path(request.query.get("name", "recording.mcap")).name or "recording.mcap"
        if self._uploads is None:
            self._uploads = tempfile.TemporaryDirectory(prefix="eyesim-replay-")
        self._uploaded += 1
        folder = Path(self._uploads.name) / str(self._uploaded)
        folder.mkdir()
        path = folder / name
        with open(path, "wb") as file:
            async for chunk in request.content.iter_chunked(1 << 20):
                file.write(chunk)
        try:
            recording = await asyncio.get_running_loop().run_in_executor(None, Recording, path)
        except RecordingError as error:
            shutil.rmtree(folder, ignore_errors=True)
            return web.Response(status=400, text=str(error).replace(str(path), name))
        await self._show(recording, owned=True)
        return web.Response(text=f"showing {name}")

    async def _show(self, recording, owned: bool) -> None:
        """Every open page shows `recording` from now on; one opened here that it replaces is closed
        (and deleted, when it was uploaded)."""
        previous, self.recording = self.recording, recording
        previous_owned, self._owned = self._owned, owned
        self.source = timeline.RecordingTimeline(recording, secrets.token_hex(4))
        if previous_owned:
            previous.close()
            if self._uploads is not None and previous.path.parent.parent == Path(self._uploads.name):
                shutil.rmtree(previous.path.parent, ignore_errors=True)
        for ws in list(self._pages):
            self._pages[ws] = timeline.FrameCursor()
            await self._introduce(ws, self._pages[ws])

    def _in_report(self, relative: str) -> Path:
        """A file of the report folder (404 for anything outside it or missing)."""
        if self.report_dir is None:  # the report routes exist only with a report folder
            raise web.HTTPNotFound()
        path = (self.report_dir / (relative or "index.html")).resolve()
        if not path.is_relative_to(self.report_dir) or not path.is_file():
            raise web.HTTPNotFound()
        return path

    async def _report_file(self, request: web.Request) -> web.StreamResponse:
        return web.FileResponse(self._in_report(request.match_info["path"]), headers={"Cache-Control": "no-cache"})

    async def _replay_case(self, request: web.Request) -> web.Response:
        """A case's recording from the report: shown on every page, then the viewer opens on it."""
        relative = request.query.get("file", "")
        path = self._in_report(relative)
        if path.suffix != ".mcap":
            raise web.HTTPNotFound()
        try:
            recording = await asyncio.get_running_loop().run_in_executor(None, Recording, path)
        except RecordingError as error:
            return web.Response(status=400, text=str(error).replace(str(path), relative))
        await self._show(recording, owned=True)
        raise web.HTTPFound("/")

    async def _introduce(self, ws: web.WebSocketResponse, cursor: timeline.FrameCursor) -> None:
        """The scene, the timeline and the first frame of the recording shown now."""
        source = self.source
        segment = source.segment_at(source.start_us)
        cursor.segment = segment.index
        await ws.send_str(json.dumps(source.scene_message(segment)))
        await ws.send_str(
            json.dumps(
                plain_messages.timeline("replay", self.recording.path.name, source.start_us / 1e6, source.end_us / 1e6)
            )
        )
        await ws.send_str(await cursor.frame(source, source.start_us))

    @staticmethod
    def _attachment_name(request: web.Request, name: str) -> str | None:
        """The attachment of the recording's scene the URL names (`?v=N`: the scene after N edits)."""
        segment = request.query.get("v", "0")
        if not (segment.isascii() and segment.isdigit() and len(segment) <= 9):
            return None
        return name if int(segment) == 0 else f"{name}@{int(segment)}"

    async def _floor_texture(self, request: web.Request) -> web.StreamResponse:
        name = self._attachment_name(request, "floor-texture")
        data = self.recording.attachment(name) if name else None
        kind = _image_kind(data) if data else None
        if kind is None:
            raise web.HTTPNotFound()
        return web.Response(body=data, content_type=kind)

    async def _mesh(self, request: web.Request) -> web.StreamResponse:
        kind, number = request.match_info["kind"], request.match_info["id"]
        if kind not in ("robot", "object") or not (number.isascii() and number.isdigit() and len(number) <= 9):
            raise web.HTTPNotFound()
        name = self._attachment_name(request, f"mesh/{kind}/{int(number)}")
        data = self.recording.attachment(name) if name else None
        if data is None:
            raise web.HTTPNotFound()
        return web.Response(body=data, content_type="application/json")

    async def _websocket(self, request: web.Request) -> web.WebSocketResponse:
        ws = web.WebSocketResponse(heartbeat=20, max_msg_size=MAX_COMMAND_BYTES)
        await ws.prepare(request)
        self._pages[ws] = timeline.FrameCursor()
        try:
            await self._introduce(ws, self._pages[ws])
            async for message in ws:
                if message.type == WSMsgType.TEXT:
                    reply = await self._answer(self._pages[ws], message.data)
                elif message.type == WSMsgType.BINARY:
                    reply = _error("binary messages are not understood: send JSON text")
                else:
                    continue
                await ws.send_str(reply)
        finally:
            del self._pages[ws]
        return ws

    async def _answer(self, cursor: timeline.FrameCursor, text: str) -> str:
        try:
            data = json.loads(text, parse_constant=_reject_constant)
        except (ValueError, RecursionError) as error:
            return _error(f"not valid JSON: {error}")
        problem = channel_schema.command_problem(data)
        if problem:
            return _error(problem)
        if data["type"] not in timeline.TIMELINE_COMMANDS:
            return _error(
                f"{reprlib.repr(data.get('type'))}: this is a replay of {self.recording.path.name}; "
                "it can be watched, not changed"
            )
        try:
            return await timeline.answer(self.source, cursor, data)
        except ValueError as error:
            return _error(str(error))


def _error(text: str) -> str:
    return json.dumps(plain_messages.error(text))


def _image_kind(data: bytes) -> str | None:
    """The Content-Type of a PNG, JPEG, BMP or GIF image, by its first bytes."""
    signatures = {b"\x89PNG": "PNG", b"\xff\xd8\xff": "JPEG", b"BM": "BMP", b"GIF8": "GIF"}
    for magic, name in signatures.items():
        if data.startswith(magic):
            return TEXTURE_TYPES[name]
    return None


async def serve(
    recording, host: str, port: int, on_ready, report_dir: Path | None = None, require_token: bool = True
) -> None:
    """Serves the replay (and the grading report in `report_dir`) until cancelled; `on_ready(server)`
    once it listens."""
    server = ReplayServer(recording, host, port, report_dir=report_dir, require_token=require_token)
    await server.start()
    on_ready(server)
    try:
        await asyncio.Event().wait()
    finally:
        await server.stop()


def serve_until_interrupted(
    path: str, host: str, port: int, open_browser: bool, report: Path | None = None, require_token: bool = True
) -> int:
    """`eyesim replay` (and `eyesim grade --serve`): the viewer over a recording, or over a grading
    report's recorded cases (`report`, its folder), until Ctrl-C; the command's exit status."""
    import webbrowser

    from eyesim import platform

    if report is not None:
        recordings = sorted(report.glob(f"cases/*/*/{RECORDING}"))
        if not recordings:
            print(
                f"eyesim replay: {report} holds no recorded case (cases/*/*/{RECORDING}); grade with "
                f"--keep-recordings all, or failed (the default) when a case failed",
                file=sys.stderr,
            )
            return 2
        path = str(recordings[0])
    try:
        recording = Recording(path)
    except RecordingError as error:
        print(f"eyesim replay: {error}", file=sys.stderr)
        return 2

    def ready(server) -> None:
        if report is not None:
            print(f"EyeSim grading report with replays: {server.report_url}", flush=True)
        print(f"EyeSim replay of {recording.path.name} ({recording.duration_s:.1f} s): {server.url}", flush=True)
        if open_browser and platform.has_display():
            webbrowser.open(server.report_url if report is not None else server.url)

    with recording:
        try:
            asyncio.run(serve(recording, host, port, ready, report_dir=report, require_token=require_token))
        except ValueError as error:  # --no-token on an address other machines reach
            print(f"eyesim replay: {error}", file=sys.stderr)
            return 2
        except OSError as error:
            print(
                f"eyesim replay: cannot serve on port {port}: {error.strerror} (try --viewer-port 0)", file=sys.stderr
            )
            return 2
        except KeyboardInterrupt:
            pass
    return 0
