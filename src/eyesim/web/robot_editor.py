"""The robot editor's JSON routes (docs/viewer.md, "Robot editor"): open, check, preview, test-drive
and save robot types, all through the loader and the simulator's own build path.

The browser edits a robot as the JSON document of the published robot schema (every field written
out, so the forms show every value). Every check goes through `json_format.parse_json`, the same
path a robot .json file takes when it is loaded, so the editor shows the loader's own messages;
each is tied to the field it is about by its JSON pointer. The preview and the test drive build the
robot with the simulator's `Simulation` (world/builder.py) in a scratch world of their own; the
running scene is never touched.

Files: robots open from and save to the scene root (the folder the simulator was started in) and
its sub-folders only; paths are relative, without `..`, and a symbolic link that leads out of the
root is refused. A file is never overwritten unless the request says so.

Every request body is checked against its definition in interface/viewer.schema.json first
(route_bodies.py); what needs the robot or the files to check is checked here."""

from __future__ import annotations

import asyncio
import base64
import dataclasses
import io
import json
import logging
import math
import os
import threading
import time
from pathlib import Path
from typing import Any

import numpy as np
from aiohttp import web
from PIL import Image

from eyesim.core.clock import REALTIME, Clock
from eyesim.physics.units import mm
from eyesim.robot.components.vw import VwController
from eyesim.scene import builtins, json_format, paths
from eyesim.scene.description import Location, Pose, RobotPlacement, RobotType, Scene, Wall, World
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.drives import DRIVES, drive_named
from eyesim.scene.jsonpos import json_positions
from eyesim.scene.loader import read_document
from eyesim.scene.placement import chassis_extent
from eyesim.scene.robi import write_robi
from eyesim.viewer import messages
from eyesim.viewer.mesh_message import has_mesh, mesh_message
from eyesim.web import scene_files
from eyesim.web.route_bodies import BadBody, checked_body
from eyesim.web.simulation_calls import on_simulation

log = logging.getLogger("eyesim.web")
PREFIX = "/robot-editor/api"
ROBOT_SUFFIXES = (".robi", ".json")
MAX_ROBOT_BYTES = 1024 * 1024  # a robot document is small; a bigger request is refused
MAX_LISTED_FILES = 2000
MAX_VISITED_FILES = 50_000  # started in a home folder: list what a quick look finds
EDITED = "robot (editor)"  # the source named in messages about the robot being edited
PREVIEW_FLOOR = 1000.0  # mm: the preview's smallest floor, the robot at its centre
ARENA = 3000.0  # mm: the test drive's square arena (at least)
ARENA_START = 0.35  # of the arena's width: where the robot starts, facing the inner wall
ANSWER_TIMEOUT = 10.0  # s a test-drive request waits for the simulation thread
IDLE_STOP = 60.0  # s without a state request (the tab was closed): the test drive stops
# What the editor always draws over the built robot (the page's defaults, none drawn); the robot's
# components fill it in (their `editor_view`, robot/component.py).
NOTHING_DRAWN: dict[str, list | None] = {"psds": [], "lidar": None, "camera": None}


class EditorError(Exception):
    """A bad request: answered with its status and message."""

    def __init__(self, message: str, status: int = 400):
        super().__init__(message)
        self.status = status


# -- files under the root ----------------------------------------------------------------------
def confined(root: Path, relative: str) -> Path:
    """`relative` inside `root`, or EditorError (403): no absolute paths, no `..`, no links out."""
    try:
        return scene_files.confined(root, relative, "the scene folder")
    except scene_files.FileAccessError as error:
        raise EditorError(str(error), 403) from None


def robot_files(root: Path) -> list[str]:
    """Robot files (.robi, and .json robot documents) under the root, as relative paths; hidden
    folders and links out of the root are skipped, and a huge folder is looked through only so far."""
    base = root.resolve()
    found, seen = [], 0
    for folder, folders, files in os.walk(base):
        folders[:] = sorted(f for f in folders if not f.startswith("."))
        seen += len(files) + len(folders)
        for name in sorted(files):
            path = Path(folder) / name
            if path.suffix.lower() not in ROBOT_SUFFIXES or name.startswith("."):
                continue
            if base not in path.resolve().parents or not path.is_file():
                continue
            if path.suffix.lower() == ".json" and not _is_robot_json(path):
                continue
            found.append(path.relative_to(base).as_posix())
        if len(found) >= MAX_LISTED_FILES or seen >= MAX_VISITED_FILES:
            break
    return sorted(found[:MAX_LISTED_FILES])


def _is_robot_json(path: Path) -> bool:
    try:
        with path.open("rb") as file:
            return b'"eyesim.robot"' in file.read(4096)
    except OSError:
        return False


# -- robot documents ---------------------------------------------------------------------------
def full_json(robot: RobotType) -> dict:
    """The robot as a JSON document with every field written out (the forms show each value)."""
    data = {"format": "eyesim.robot", "version": json_format.VERSION}
    for field in dataclasses.fields(robot):
        if field.name == "source":
            continue
        value = _plain(getattr(robot, field.name))
        if value is not None:
            data[field.name] = value
    return data


def _plain(value):
    if dataclasses.is_dataclass(value):
        return {
            f.name: _plain(getattr(value, f.name))
            for f in dataclasses.fields(value)
            if getattr(value, f.name) is not None
        }
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    return value


def new_robot(drive_name: str) -> RobotType:
    """An empty robot of a drive type: a chassis and what the drive needs to move (as the loader
    completes it)."""
    drive = drive_named(drive_name)
    if drive is None:
        raise EditorError(f"unknown drive {drive_name!r}: expected one of {', '.join(d.name for d in DRIVES)}")
    robot, problems = check_document(full_json(RobotType(name="NewRobot", source=EDITED, drive=drive.name)))
    if robot is None:  # the simulator's own fault: said as such, not as a failed full_json(None)
        raise EditorError(f"a new {drive.name} robot does not load: " + "; ".join(p["message"] for p in problems), 500)
    return robot


def check_document(document) -> tuple[RobotType | None, list[dict]]:
    """The robot a JSON document describes, through the loader's JSON path, and its problems,
    each with the JSON pointer of the field it is about ('' for the robot as a whole)."""
    if not isinstance(document, dict):
        raise EditorError("expected the robot as a JSON object")
    text = json.dumps(document, indent=2)
    diagnostics = Diagnostics()
    kind, robot = json_format.parse_json(text, EDITED, diagnostics, ("robot",))
    return robot, _problems(diagnostics, text)


def _problems(diagnostics: Diagnostics, text: str) -> list[dict]:
    try:
        values, keys = json_positions(text)
    except (ValueError, RecursionError):
        values, keys = {}, {}
    at = {position: path for path, position in keys.items()}
    at.update({position: path for path, position in values.items()})
    problems = []
    for d in diagnostics.items:
        path = at.get((d.location.line, d.location.column), ())
        message = d.message
        pointer = json_format.pointer(list(path)) if path else ""
        if pointer and message.startswith(pointer + ": "):
            message = message[len(pointer) + 2 :]  # the field shows where; the text says what
        problems.append({"kind": d.kind, "pointer": pointer, "message": message, "code": d.code})
    return problems


def open_robot(root: Path, source: str) -> tuple[RobotType, Path | None, list[dict]]:
    """'builtin:<name>', 'file:<relative path>' or 'new:<drive>' -> (robot, its file, problems)."""
    kind, _, name = source.partition(":") if isinstance(source, str) else ("", "", "")
    if kind == "new":
        return new_robot(name), None, []
    if kind == "builtin":
        path = builtins.robot_path(name)
        if path is None:
            raise EditorError(f"no built-in robot {name!r}: expected one of {', '.join(builtins.robot_names())}", 404)
    elif kind == "file":
        path = confined(root, name)
        if path.suffix.lower() not in ROBOT_SUFFIXES:
            raise EditorError(f"{name!r}: expected a .robi or .json robot file")
        if not path.is_file():
            raise EditorError(f"{name!r}: no such file in the scene folder", 404)
    else:
        raise EditorError(f"{source!r}: expected builtin:<name>, file:<path> or new:<drive>")
    paths.clear_cache()
    diagnostics = Diagnostics()
    _, robot = read_document(path, diagnostics, ("robot",))
    problems = [{"kind": d.kind, "pointer": "", "message": str(d), "code": d.code} for d in diagnostics.items]
    if robot is None:
        raise EditorError("; ".join(p["message"] for p in problems if p["kind"] == "error") or "not a robot")
    return robot, path, problems


def save_robot(root: Path, robot: RobotType, relative: str, overwrite: bool, origin: Path | None = None) -> Path:
    """Writes the robot as .robi or JSON (by the name's ending) under the root; `origin`, the file
    it came from, keeps its model reference pointing at the same model file."""
    path = confined(root, relative)
    suffix = path.suffix.lower()
    if suffix not in ROBOT_SUFFIXES:
        raise EditorError(f"{relative!r}: expected a name ending in .robi or .json")
    if not path.parent.is_dir():
        raise EditorError(
            f"{relative!r}: the folder {path.parent.relative_to(root.resolve()).as_posix()!r} does not exist", 404
        )
    if path.exists() and not overwrite:
        raise EditorError(f"{relative!r} exists: overwrite it?", 409)
    if path.is_symlink() or (path.exists() and not path.is_file()):
        raise EditorError(f"{relative!r} is not a plain file: not overwritten", 403)
    robot = moved_model(robot, origin, path)
    text = write_robi(robot) if suffix == ".robi" else json_format.dumps(json_format.to_json("robot", robot))
    path.write_text(text, encoding="utf-8")
    return path


def moved_model(robot: RobotType, origin: Path | None, target: Path) -> RobotType:
    """The robot with its model reference written from `target`'s folder, so that a robot saved
    somewhere else than it came from still finds its model."""
    if robot.model is None or origin is None or origin.parent.resolve() == target.parent.resolve():
        return robot
    found = paths.resolve(robot.model, origin)
    if found is None:
        return robot
    return dataclasses.replace(robot, model=Path(os.path.relpath(found, target.parent.resolve())).as_posix())


def resolved_model(robot: RobotType, origin: Path | None) -> RobotType:
    """The robot with its model file found as the loader finds it (relative to where it came from)."""
    if robot.model is None:
        return robot
    found = paths.resolve(robot.model, origin) if origin is not None else None
    return dataclasses.replace(robot, model=str(found) if found else None)


# -- building: preview and test drive ----------------------------------------------------------
def scratch_scene(robot: RobotType, floor: float, walls: tuple[Wall, ...] = (), at: float = 0.5) -> Scene:
    """The robot alone on a square floor, `at` of the way along x, halfway along y, facing +x."""
    world = World(EDITED, floor, floor, walls=walls)
    placement = RobotPlacement(robot.name, Pose(floor * at, floor / 2, 0.0), location=Location(EDITED))
    return Scene(EDITED, world, {robot.name: robot}, robots=(placement,))


def arena_size(robot: RobotType) -> float:
    """The test arena grows with the robot, so a big one fits with room to move."""
    return max(ARENA, 6 * max(robot.length, robot.width))


def arena_walls(size: float) -> tuple[Wall, ...]:
    """A square room with an inner wall ahead of the robot, so PSDs, the lidar and the camera see something."""
    a = size
    return (
        Wall(0, 0, a, 0),
        Wall(a, 0, a, a),
        Wall(a, a, 0, a),
        Wall(0, a, 0, 0),
        Wall(a * 0.75, a * 0.3, a * 0.75, a * 0.7, color=(200, 60, 60)),
    )


def build(robot: RobotType, floor: float, walls=(), clock: Clock | None = None, at: float = 0.5):
    from eyesim.core.engine import Simulation  # the engine pulls in the physics: only when building

    return Simulation(scratch_scene(robot, floor, walls, at), clock)


def preview_of(sim, mesh: str) -> dict:
    """The built robot as the viewer gets it (its scene message, with the mesh served from `mesh`)
    and its sensors."""
    robot = sim.robots[0]
    message = messages.scene(sim, None)
    for entry in message["robots"]:
        entry.pop("mesh", None)
        if has_mesh(sim, robot.body):
            entry["mesh"] = mesh
    return {"scene": message, **sensors(sim)}


def sensors(sim) -> dict:
    """What the editor draws over the built robot: the poses and what its components show (each
    PSD's beam, the lidar's scan plane, the camera's view; world frame, m)."""
    drawn = _gathered(sim.robots[0], "editor_view", NOTHING_DRAWN)
    return {"snapshot": messages.snapshot(sim), **drawn}


def _gathered(robot, hook: str, start: dict) -> dict:
    """The components' answers to a hook that returns named entries (robot/component.py): a list
    adds to the list of its name, another value is the entry; arrays as rounded lists, images as
    JPEG (base64)."""
    gathered: dict[str, Any] = {
        name: list(value) if isinstance(value, list) else value for name, value in start.items()
    }
    for component in robot.components:
        for name, value in getattr(component, hook)().items():
            if isinstance(value, list):
                gathered.setdefault(name, []).extend(_plain_values(v) for v in value)
            elif isinstance(value, dict) and isinstance(gathered.get(name), dict):
                gathered[name].update(_plain_values(value))
            else:
                gathered[name] = _plain_values(value)
    return gathered


def _plain_values(value):
    """Arrays as rounded lists, an image (height x width x 3 bytes) as JPEG; in dicts too."""
    if isinstance(value, dict):
        return {key: _plain_values(v) for key, v in value.items()}
    if isinstance(value, np.ndarray):
        return _jpeg(value) if value.dtype == np.uint8 and value.ndim == 3 else _list(value)
    return value


def _list(values) -> list[float]:
    return [round(float(v), 5) for v in np.asarray(values).ravel()]


class TestDrive:
    """The robot in a scratch arena, simulated in real time on a thread of its own."""

    def __init__(self, robot: RobotType):
        self.robot_type = robot
        size = arena_size(robot)
        self.sim = build(robot, size, arena_walls(size), Clock(REALTIME), at=ARENA_START)
        self.last_seen = time.monotonic()
        self.sim.schedule(0, self._watch)
        self.thread = threading.Thread(target=self.sim.run, name="eyesim-test-drive", daemon=True)
        self.thread.start()

    def on_sim(self, action):
        """`action(sim)` on the simulation thread; its result as an awaitable."""
        return asyncio.wait_for(on_simulation(self.sim, action), ANSWER_TIMEOUT)

    def stop(self) -> None:
        self.sim.stop()
        self.thread.join(timeout=5)
        if not self.thread.is_alive():
            self.sim.close()

    def _watch(self, sim) -> None:
        """Once a simulated second: a test drive nobody looks at any more ends by itself."""
        if time.monotonic() - self.last_seen > IDLE_STOP:
            log.info("robot editor: test drive stopped (no page asked for it for %.0f s)", IDLE_STOP)
            sim.stop()
        else:
            sim.schedule(sim.time_us + 1_000_000, self._watch)

    # -- on the simulation thread ---------------------------------------------------------
    def command(self, sim, message: dict) -> None:
        """A DriveCommand of the schema (its fields' types and ranges checked)."""
        robot = sim.robots[0]
        kind = message["type"]
        if kind == "vw":
            vw = robot.component(VwController)
            if vw is None:
                raise EditorError(f"a {robot.type.drive} robot has no V-omega drive: use its motors or servos")
            try:
                vw.set_speed(mm(message["v"]), math.radians(message["w"]))
            except ValueError as error:
                raise EditorError(str(error)) from None
        elif kind == "motor":
            number, speed = message["motor"], message["speed"]
            motor = robot.motors.get(number)
            if motor is None:
                raise EditorError(f"no motor {number} (motors: {sorted(robot.motors) or 'none'})")
            for vw in robot.components_of(VwController):
                if motor in vw.drive.motors.values():
                    vw.release()
            motor.drive(round(speed))
        elif kind == "servo":
            number, position = message["servo"], message["position"]
            servo = robot.servos.get(number)
            if servo is None:
                raise EditorError(f"no servo {number} (servos: {sorted(robot.servos) or 'none'})")
            servo.set(round(position))
        else:  # reset
            sim.reset()

    def state(self, sim) -> dict:
        self.last_seen = time.monotonic()
        robot = sim.robots[0]
        # the readings first: sensors() draws the lidar scan they take
        readings = _gathered(
            robot, "readings", {"psd": {}, "servos": sorted(robot.servos), "motors": sorted(robot.motors)}
        )
        vw = robot.component(VwController)
        if vw is not None:
            v, w = vw.measured_speed()
            readings["vw"] = [round(v * 1000), round(math.degrees(w))]
        return {**sensors(sim), "time": sim.time, "readings": readings}


def _jpeg(pixels) -> str:
    buffer = io.BytesIO()
    Image.fromarray(pixels).save(buffer, format="JPEG", quality=85)
    return base64.b64encode(buffer.getvalue()).decode("ascii")


# -- the routes --------------------------------------------------------------------------------
class RobotEditor:
    """The editor's state on the server: the last preview and the test drive, if one runs."""

    def __init__(self, root: Path):
        self.root = Path(root)
        self.preview = None  # the last preview's Simulation (its mesh is served from it)
        self.drive: TestDrive | None = None
        self.lock = asyncio.Lock()  # one build at a time

    def add_routes(self, app: web.Application) -> None:
        """Routes under /robot-editor/api; the app's middleware (access.py) guards each of them."""
        app.router.add_get(f"{PREFIX}/schema", self._schema)
        app.router.add_get(f"{PREFIX}/sources", self._sources)
        app.router.add_post(f"{PREFIX}/open", self._open)
        app.router.add_post(f"{PREFIX}/check", self._check)
        app.router.add_post(f"{PREFIX}/save", self._save)
        app.router.add_post(f"{PREFIX}/drive/start", self._drive_start)
        app.router.add_post(f"{PREFIX}/drive/command", self._drive_command)
        app.router.add_get(f"{PREFIX}/drive/state", self._drive_state)
        app.router.add_post(f"{PREFIX}/drive/stop", self._drive_stop)
        app.router.add_get(PREFIX + "/mesh/{which}", self._mesh)
        app.on_cleanup.append(self._cleanup)

    async def _cleanup(self, app) -> None:
        self.stop_drive()

    def stop_drive(self) -> None:
        if self.drive is not None:
            self.drive.stop()
            self.drive = None

    async def _schema(self, request: web.Request) -> web.Response:
        return web.json_response(json_format.schema("robot"))

    async def _sources(self, request: web.Request) -> web.Response:
        files = await asyncio.get_running_loop().run_in_executor(None, robot_files, self.root)
        return web.json_response(
            {
                "builtins": builtins.robot_names(),
                "files": files,
                "drives": [d.name for d in DRIVES],
                "drive_parts": {d.name: list(d.parts) for d in DRIVES},
            }
        )

    async def _open(self, request: web.Request) -> web.Response:
        return await _answer(request, self._opened)

    async def _opened(self, body: dict) -> dict:
        robot, path, problems = await _off_loop(open_robot, self.root, body["source"])
        origin = (
            path.resolve().relative_to(self.root.resolve()).as_posix()
            if path is not None and self.root.resolve() in path.resolve().parents
            else None
        )
        source = body["source"]
        builtin = source.partition(":")[2] if source.startswith("builtin:") else None
        return {"robot": full_json(robot), "origin": origin, "builtin": builtin, "problems": problems}

    def _origin(self, body: dict) -> Path | None:
        """The file the robot came from (models are found relative to it)."""
        origin, name = body.get("origin"), body.get("builtin")
        if isinstance(name, str) and builtins.robot_path(name) is not None:
            return builtins.robot_path(name)
        return confined(self.root, origin) if isinstance(origin, str) and origin else None

    async def _check(self, request: web.Request) -> web.Response:
        return await _answer(request, self._checked)

    async def _checked(self, body: dict) -> dict:
        robot, problems = check_document(body["robot"])
        if robot is None:
            return {"problems": problems, "preview": None}
        origin = self._origin(body)
        async with self.lock:
            floor = max(PREVIEW_FLOOR, 3 * max(robot.length, robot.width))
            try:
                sim = await _off_loop(build, resolved_model(robot, origin), floor)
            except ValueError:  # a robot with errors may not build (two bumpers on one line)
                if not any(p["kind"] == "error" for p in problems):
                    raise
                return {"problems": problems, "preview": None}
            if self.preview is not None:
                self.preview.close()
            self.preview = sim
            preview = await _off_loop(preview_of, sim, f"{PREFIX}/mesh/preview")
        return {
            "problems": problems,
            "preview": preview,
            "robi": write_robi(robot),
            "chassis": list(chassis_extent(robot)),
        }

    async def _save(self, request: web.Request) -> web.Response:
        return await _answer(request, self._saved)

    async def _saved(self, body: dict) -> dict:
        robot, problems = check_document(body["robot"])
        if robot is None:
            raise EditorError(
                "the robot has errors: "
                + "; ".join(f"{p['pointer'] or 'robot'}: {p['message']}" for p in problems if p["kind"] == "error")
            )
        path = await _off_loop(
            save_robot, self.root, robot, body["path"], body.get("overwrite") is True, self._origin(body)
        )
        diagnostics = Diagnostics()
        _, again = read_document(path, diagnostics, ("robot",))  # what `eyesim check` will say
        return {
            "path": path.relative_to(self.root.resolve()).as_posix(),
            "problems": [{"kind": d.kind, "pointer": "", "message": str(d), "code": d.code} for d in diagnostics.items],
            "loads": again is not None,
        }

    async def _drive_start(self, request: web.Request) -> web.Response:
        return await _answer(request, self._drive_started)

    async def _drive_started(self, body: dict) -> dict:
        robot, problems = check_document(body["robot"])
        if robot is None:
            raise EditorError("fix the robot's errors before a test drive")
        robot = resolved_model(robot, self._origin(body))
        async with self.lock:
            self.stop_drive()
            self.drive = await _off_loop(TestDrive, robot)
            message = await self.drive.on_sim(lambda sim: messages.scene(sim, None))
        for entry in message["robots"]:
            if "mesh" in entry:
                entry["mesh"] = f"{PREFIX}/mesh/drive"
        return {"scene": message}

    async def _drive_command(self, request: web.Request) -> web.Response:
        return await _answer(request, self._drive_commanded)

    async def _drive_commanded(self, body: dict) -> dict:
        drive = self._running_drive()
        await drive.on_sim(lambda sim: drive.command(sim, body))
        return {"ok": True}

    async def _drive_state(self, request: web.Request) -> web.Response:
        try:
            drive = self._running_drive()
            return web.json_response(await drive.on_sim(drive.state))
        except EditorError as error:
            return web.json_response({"error": str(error)}, status=error.status)
        except asyncio.TimeoutError:
            return web.json_response({"error": "the test drive did not answer"}, status=504)

    async def _drive_stop(self, request: web.Request) -> web.Response:
        return await _answer(request, self._drive_stopped)

    async def _drive_stopped(self, body: dict) -> dict:
        await _off_loop(self.stop_drive)
        return {"ok": True}

    def _running_drive(self) -> TestDrive:
        if self.drive is None or not self.drive.thread.is_alive():
            raise EditorError("no test drive is running: start one first", 409)
        return self.drive

    async def _mesh(self, request: web.Request) -> web.Response:
        which = request.match_info["which"]
        sim = self.preview if which == "preview" else self.drive.sim if which == "drive" and self.drive else None
        if sim is None or not has_mesh(sim, sim.robots[0].body):
            raise web.HTTPNotFound()
        text = await _off_loop(lambda: json.dumps(mesh_message(sim.world.model, sim.robots[0].body)))
        return web.Response(text=text, content_type="application/json")


async def _off_loop(function, *args):
    return await asyncio.get_running_loop().run_in_executor(None, function, *args)


async def _answer(request: web.Request, handler) -> web.Response:
    """Reads and checks the JSON body, runs `handler(body)`; a bad request gets its status and message."""
    try:
        body = await checked_body(request, MAX_ROBOT_BYTES)
        return web.json_response(await handler(body))
    except (BadBody, EditorError) as error:
        return web.json_response({"error": str(error)}, status=error.status)
    except Exception:  # noqa: BLE001 - the editor's request fails, the simulator goes on
        log.exception("robot editor: %s failed", request.path)
        return web.json_response({"error": f"{request.path}: the simulator could not carry this out"}, status=500)
