"""The page's program and settings controls: JSON routes under /api (docs/viewer.md).

Per robot: start, stop and restart a program (an executable or .py file under the scene roots,
program_files.py), and compile C/C++ sources there with `eyesim cc`. What the programs print and
how they end reaches the page as the usual console and program events. Settings (PSD noise and
seed, VIS, TRACE) change the running scene's description, so a save writes them.

Every route is behind the viewer's access checks (access.py), and every body is checked against
its definition in interface/viewer.schema.json (route_bodies.py). Bad requests get 400 and a JSON
{"error": ...} saying what was wrong; nothing else changes."""

from __future__ import annotations

import asyncio
import contextlib
import dataclasses
import logging
import re
import subprocess
from pathlib import Path

from aiohttp import web

from eyesim.programs import toolchain
from eyesim.viewer import messages
from eyesim.web import program_files
from eyesim.web.route_bodies import BadBody, checked_body
from eyesim.web.simulation_calls import on_simulation
from eyesim.web.scene_files import FileAccessError

log = logging.getLogger("eyesim.web")
COMPILE_SECONDS = 120  # a compiler that takes longer is stopped
FREE_ROBOT_SECONDS = 5.0  # how long a restart waits for the old program's connection to close
MAX_BODY = 64 * 1024
# gcc and clang: "file:line:column: error: message" (column optional)
DIAGNOSTIC = re.compile(
    r"^(?P<file>[^:\n]+):(?P<line>\d+):(?:(?P<column>\d+):)? "
    r"(?P<kind>fatal error|error|warning|note): (?P<message>.*)$",
    re.MULTILINE,
)


class BadRequest(Exception):
    """A request refused with the reason: 400, or the status given (403 a path out of the roots)."""

    def __init__(self, message: str, status: int = 400):
        super().__init__(message)
        self.status = status


class ProgramControl:
    def __init__(self, sim, launcher, run_folder: Path, resend_scene):
        self.sim = sim
        self.launcher = launcher
        self.run_folder = run_folder
        self.resend_scene = resend_scene  # tells the browsers the scene changed (VIS, TRACE)
        self.chosen: dict[int, Path] = {}  # robot id -> the program the page last started for it
        self._busy: set[int] = set()  # robots whose program is being started or stopped

    def add_routes(self, router: web.UrlDispatcher) -> None:
        router.add_get("/api/programs", self.json_route(self.overview))
        router.add_post("/api/programs/start", self.json_route(self.start))
        router.add_post("/api/programs/stop", self.json_route(self.stop))
        router.add_post("/api/programs/restart", self.json_route(self.restart))
        router.add_post("/api/programs/compile", self.json_route(self.compile))
        router.add_get("/api/settings", self.json_route(self.settings))
        router.add_post("/api/settings", self.json_route(self.change_settings))

    def roots(self) -> list[program_files.Root]:
        return program_files.scene_roots(self.run_folder, self.sim.scene.source)

    # -- routes -------------------------------------------------------------------------------
    async def overview(self, _body: dict) -> dict:
        roots = self.roots()
        files = await asyncio.get_running_loop().run_in_executor(None, program_files.list_files, roots)
        return {
            "roots": [{"name": r.name, "path": str(r.path)} for r in roots],
            "files": files,
            "robots": [self._robot_state(robot, roots) for robot in self.sim.robots],
        }

    async def start(self, body: dict) -> dict:
        robot = self.robot(body)
        path = self._file(body, kinds=("executable", "python"))
        return await self.restart_with(robot, path)

    async def restart(self, body: dict) -> dict:
        robot = self.robot(body)
        path = self.program_of(robot)
        if path is None:
            raise BadRequest(f"robot {robot.id} has no program to restart: start one first")
        return await self.restart_with(robot, path)

    async def stop(self, body: dict) -> dict:
        robot = self.robot(body)
        run = self.launcher.latest(robot.id)
        if run is None or run.process is None or run.process.poll() is not None:
            raise BadRequest(f"robot {robot.id} runs no program")
        async with self._robot_busy(robot.id):
            await asyncio.get_running_loop().run_in_executor(None, self.launcher.stop, run)
        return self._robot_state(robot, self.roots())

    async def compile(self, body: dict) -> dict:
        roots = self.roots()
        source = self._file(body, kinds=("c", "c++"))
        language = "cc" if program_files.kind_of(source) == "c" else "c++"
        output = toolchain.executable_name(source.with_suffix(""))
        root = roots[body["root"]].path
        args = [
            toolchain.source_argument(source.relative_to(root).as_posix()),
            "-o",
            toolchain.source_argument(output.relative_to(root).as_posix()),
        ]
        command = toolchain.compiler_command(language, args)
        result = await asyncio.get_running_loop().run_in_executor(None, _run_compiler, command, root)
        if result.returncode == 0:
            toolchain.place_library(args, cwd=root)
        text = result.stdout + result.stderr
        return {
            "ok": result.returncode == 0,
            "output": text,
            "diagnostics": [diagnostic(match) for match in DIAGNOSTIC.finditer(text)],
            "program": program_files.locate(roots, output) if result.returncode == 0 else None,
        }

    async def settings(self, _body: dict) -> dict:
        settings = self.sim.scene.settings
        clock = {
            key: value
            for key, value in messages.status(self.sim, None).items()
            if key in ("time", "paused", "speed", "clock")
        }
        return {
            "vis": settings.vis,
            "trace": settings.trace,
            "psd_noise": settings.psd_noise,
            "seed": settings.seed,
            **clock,
        }

    async def change_settings(self, body: dict) -> dict:
        """Any of vis, trace, psd_noise and seed (their types and ranges are the schema's)."""
        changes = dict(body)
        if "psd_noise" in changes:
            changes["psd_noise"] = float(changes["psd_noise"])
        if changes:
            await self._on_simulation(lambda sim: apply_settings(sim, **changes))
            self.resend_scene()
        return await self.settings({})

    # -- helpers ------------------------------------------------------------------------------
    async def restart_with(self, robot, path: Path) -> dict:
        """Stop the robot's program if it runs, then start `path` for it (a C/C++ source is built
        first, or taken from the build cache: programs/sources.py)."""
        async with self._robot_busy(robot.id):
            run = self.launcher.latest(robot.id)
            loop = asyncio.get_running_loop()
            if run is not None and run.process is not None and run.process.poll() is None:
                await loop.run_in_executor(None, self.launcher.stop, run)
            await self._robot_free(robot.id)
            self.chosen[robot.id] = path
            await loop.run_in_executor(None, self.launcher.start, robot.id, path)
        return self._robot_state(robot, self.roots())

    async def _robot_free(self, robot_id: int) -> None:
        """Wait until no program holds the robot (the stopped one's connection has closed)."""
        loop = asyncio.get_running_loop()
        deadline = loop.time() + FREE_ROBOT_SECONDS
        while loop.time() < deadline:
            held = await self._on_simulation(
                lambda sim: any(s.robot is not None and s.robot.id == robot_id and not s.closed for s in sim.sessions)
            )
            if not held:
                return
            await asyncio.sleep(0.05)
        raise BadRequest(
            f"robot {robot_id} is still held by a program the simulator did not start (stop it where it runs)"
        )

    @contextlib.asynccontextmanager
    async def _robot_busy(self, robot_id: int):
        """One start, stop or restart per robot at a time (a double click must not start two)."""
        if robot_id in self._busy:
            raise BadRequest(f"robot {robot_id}: its program is being started or stopped, try again")
        self._busy.add(robot_id)
        try:
            yield
        finally:
            self._busy.discard(robot_id)

    async def _on_simulation(self, action):
        """Run action(sim) on the simulation thread and return its result."""
        return await on_simulation(self.sim, action)

    def robot(self, body: dict):
        robot = self.sim.robot_by_id(body["robot"])
        if robot is None:
            raise BadRequest(f"no robot {body['robot']}")
        return robot

    def _file(self, body: dict, kinds: tuple[str, ...]) -> Path:
        try:
            path = program_files.resolve(self.roots(), body["root"], body["path"])
        except FileAccessError as error:
            raise BadRequest(str(error)) from None
        kind = program_files.kind_of(path)
        if kind not in kinds:
            what = "a program (an executable or a .py file)" if "python" in kinds else "a C or C++ source"
            raise BadRequest(f"{body['path']!r} is not {what}")
        return path

    def program_of(self, robot) -> Path | None:
        """What Restart runs: the page's last choice, else what the robot ran (a C/C++ source it
        was built from: built again when the source changed), else the scene's."""
        if robot.id in self.chosen:
            return self.chosen[robot.id]
        run = self.launcher.latest(robot.id)
        if run is not None:
            return run.source or run.path
        placement = self.sim.scene.robots[robot.id - 1] if robot.id <= len(self.sim.scene.robots) else None
        return Path(placement.program) if placement is not None and placement.program else None

    def _robot_state(self, robot, roots) -> dict:
        run = self.launcher.latest(robot.id)
        program = self.program_of(robot)
        state = {
            "id": robot.id,
            "name": robot.name,
            "program": None
            if program is None
            else (program_files.locate(roots, program) or {"root": None, "path": str(program)}),
            "state": "none",
            "exit_code": None,
            "reason": None,
        }
        if run is None:
            return state
        if run.error:
            state.update(state="failed", reason=run.error)
        elif run.process is not None and run.process.poll() is None:
            state.update(state="running")
        else:
            state.update(state="stopped" if run.stopped_by_us else "exited", exit_code=run.exit_code)
            if run.crash is not None:
                state["reason"] = run.crash
        return state

    def json_route(self, handler, limit: int = MAX_BODY):
        """An aiohttp handler for handler(checked JSON body) -> JSON answer, refusals as {"error"}."""

        async def route(request: web.Request) -> web.Response:
            try:
                body = await checked_body(request, limit) if request.method == "POST" else {}
                return web.json_response(await handler(body))
            except BadBody as error:
                return _error(str(error), error.status)
            except BadRequest as error:
                return _error(str(error), error.status)
            except (toolchain.LibraryMissing, toolchain.CompilerMissing) as error:
                return _error(str(error), 500)
            except Exception:  # a bug: this request fails, the simulator goes on
                log.exception("viewer request %s failed", request.path)
                return _error(f"{request.path}: the simulator could not carry out this request", 500)

        return route


def apply_settings(sim, **changes) -> None:
    """New settings for the running scene, on the simulation thread: the scene description
    (what a save writes) and the components that follow them (the PSDs, whose noise restarts
    from the seed)."""
    settings = dataclasses.replace(sim.scene.settings, **changes)
    sim.scene = dataclasses.replace(sim.scene, settings=settings)
    for robot in sim.robots:
        for component in robot.components:
            component.settings_changed(settings)


def _run_compiler(command: list[str], cwd: Path) -> subprocess.CompletedProcess:
    try:
        return subprocess.run(
            command, cwd=cwd, capture_output=True, text=True, errors="replace", timeout=COMPILE_SECONDS
        )
    except FileNotFoundError:
        return subprocess.CompletedProcess(
            command, 1, "", f"compiler {command[0]!r} not found; install one or set CC / CXX\n"
        )
    except subprocess.TimeoutExpired:
        return subprocess.CompletedProcess(
            command, 1, "", f"the compiler took longer than {COMPILE_SECONDS} s and was stopped\n"
        )


def diagnostic(match: re.Match) -> dict:
    """One finding of the compiler's (DIAGNOSTIC) as the page gets it."""
    return {
        "file": match["file"],
        "line": int(match["line"]),
        "column": int(match["column"]) if match["column"] else None,
        "kind": "error" if match["kind"] == "fatal error" else match["kind"],
        "message": match["message"],
    }


def _error(message: str, status: int = 400) -> web.Response:
    return web.json_response({"error": message}, status=status)
