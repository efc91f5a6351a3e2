"""The page's program editor: read, save, check and run the source of a robot's program
(docs/viewer.md, "Program editor"). JSON routes under /api/sources.

Sources are named as every file the page names, by root and a path relative to it, under the
scene roots (program_files.py: the folder `eyesim run` was started in and the running scene's
folder, which the scene browser changes). Only program sources and their headers can be read or
written (.c .cc .cpp .cxx .h .hpp .hh .py), never created: a path that is absolute, climbs with
`..`, leads out of its root through a symbolic link or names another kind of file is refused
with 403, and the viewer's token and Origin checks (access.py) come before any of this.

Checking builds a C/C++ source exactly as `--program 1=drive.c` does, into the build cache
(programs/sources.py), so Run then starts that build; a Python file is compiled by py_compile in
a process of its own (programs/python_check.py). Either way the diagnostics come back with their
lines."""

from __future__ import annotations

import asyncio
import hashlib
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from aiohttp import web

from eyesim import paths
from eyesim.programs import sources
from eyesim.web.program_control import DIAGNOSTIC, BadRequest, ProgramControl, diagnostic
from eyesim.web.program_files import Root, locate
from eyesim.web.scene_files import FileAccessError, confined

KINDS = {
    ".c": "c",
    ".cc": "c++",
    ".cpp": "c++",
    ".cxx": "c++",
    ".h": "header",
    ".hpp": "header",
    ".hh": "header",
    ".py": "python",
}
MAX_SOURCE = 1_000_000  # bytes of a source the editor opens or saves
MAX_SAVE_BODY = 6 * MAX_SOURCE + 4096  # a JSON string may escape each byte (\u0001)
CHECK_SECONDS = 60  # a Python check that takes longer is stopped


class ProgramSources:
    def __init__(self, control: ProgramControl):
        self.control = control  # its roots, robots, programs and restarts
        self._checking: set[Path] = set()  # sources being compiled now

    def add_routes(self, router: web.UrlDispatcher) -> None:
        router.add_post("/api/sources/robot", self.control.json_route(self.of_robot))
        router.add_post("/api/sources/read", self.control.json_route(self.read))
        router.add_post("/api/sources/save", self.control.json_route(self.save, MAX_SAVE_BODY))
        router.add_post("/api/sources/check", self.control.json_route(self.check))
        router.add_post("/api/sources/run", self.control.json_route(self.run))

    # -- routes -------------------------------------------------------------------------------
    async def of_robot(self, body: dict) -> dict:
        """The source of the robot's program (what Restart runs), opened."""
        robot = self.control.robot(body)
        program = self.control.program_of(robot)
        if program is None:
            raise BadRequest(f"robot {robot.id} has no program: choose a source in the list and open it", 404)
        source = source_of(sources.locate(program))
        if source is None:
            raise BadRequest(
                f"robot {robot.id} runs {program.name}, a program with no source beside it "
                f"({program.stem}.c, .cpp or .py): choose a source in the list and open it",
                404,
            )
        roots = self.control.roots()
        place = locate(roots, source)
        if place is None:
            raise BadRequest(
                f"robot {robot.id}'s program source {source} is outside the "
                f"{' and the '.join(r.name for r in roots)}: the page may not open it",
                403,
            )
        return await self.read(place)

    async def read(self, body: dict) -> dict:
        path = self._source(body)
        data = _read(path)
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as error:
            raise BadRequest(
                f"{body['path']!r} is not UTF-8 text (byte {error.start}): the editor cannot show it"
            ) from None
        return {
            "root": body["root"],
            "path": body["path"],
            "kind": KINDS[path.suffix.lower()],
            "text": text,
            "version": _version(data),
        }

    async def save(self, body: dict) -> dict:
        """Replace the file's text. With `version` (what read answered), only when the file is still
        that version: a file changed meanwhile (another editor) is not overwritten unasked (409)."""
        path = self._source(body)
        if not self.control.roots()[body["root"]].writable or paths.PACKAGE_DIR in path.parents:
            raise BadRequest(
                f"{body['path']!r} belongs to the installed EyeSim (an example): copy it into your folder to change it",
                403,
            )
        data = body["text"].encode("utf-8")
        if len(data) > MAX_SOURCE:
            raise BadRequest(f"{len(data)} bytes: more than the editor saves ({MAX_SOURCE})", 413)
        if "version" in body and body["version"] != _version(_read(path)):
            raise BadRequest(
                f"{body['path']} changed on disk since it was opened: reopen it, or save again to replace it", 409
            )
        _replace(path, data)
        return {
            "root": body["root"],
            "path": body["path"],
            "kind": KINDS[path.suffix.lower()],
            "version": _version(data),
        }

    async def check(self, body: dict) -> dict:
        path = self._source(body)
        kind = KINDS[path.suffix.lower()]
        if kind == "header":
            raise BadRequest(f"{body['path']!r} is a header: it is checked with the program that includes it")
        if path in self._checking:
            raise BadRequest(f"{body['path']} is being compiled already: wait for that", 409)
        self._checking.add(path)
        try:
            work = _check_python if kind == "python" else _check_c
            return await asyncio.get_running_loop().run_in_executor(None, work, path)
        finally:
            self._checking.discard(path)

    async def run(self, body: dict) -> dict:
        """Start the source for the robot (stopping its program): a C/C++ source as its cached build."""
        robot = self.control.robot(body)
        path = self._source(body)
        if KINDS[path.suffix.lower()] == "header":
            raise BadRequest(f"{body['path']!r} is a header, not a program")
        return await self.control.restart_with(robot, path)

    # -- helpers ------------------------------------------------------------------------------
    def _source(self, body: dict) -> Path:
        """The real path of the source the page names: an existing file of a source kind under a root."""
        roots: list[Root] = self.control.roots()
        number, relative = body["root"], body["path"]
        if not 0 <= number < len(roots):
            raise BadRequest(f"no scene root {number} (there are {len(roots)})", 404)
        root = roots[number]
        try:
            path = confined(root.path, relative, f"the {root.name} {root.path}")
        except FileAccessError as error:
            raise BadRequest(str(error), 403) from None
        if path.suffix.lower() not in KINDS:
            raise BadRequest(
                f"{relative!r} is not a program source: the editor opens only {', '.join(KINDS)} files", 403
            )
        if not path.is_file():
            raise BadRequest(f"{relative!r}: no such file in the {root.name} {root.path}", 404)
        return path


def source_of(program: Path) -> Path | None:
    """The source a program is run from: itself when it is one, else the source beside the
    executable with its name (`drive` or `drive.x` -> `drive.c`), else None."""
    if program.suffix.lower() in KINDS:
        return program
    for suffix in paths.PROGRAM_SOURCE_SUFFIXES:
        candidate = program.with_name(program.stem + suffix)
        if candidate.is_file():
            return candidate
    return None


def _read(path: Path) -> bytes:
    try:
        if path.stat().st_size > MAX_SOURCE:
            raise BadRequest(f"{path.name} is larger than the editor opens ({MAX_SOURCE} bytes)", 413)
        return path.read_bytes()
    except OSError as error:
        raise BadRequest(f"{path.name}: {error.strerror}", 500) from None


def _replace(path: Path, data: bytes) -> None:
    """Write the file whole or not at all (a full disk leaves the old text), keeping its mode."""
    try:
        mode = path.stat().st_mode & 0o7777
        handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
        try:
            with os.fdopen(handle, "wb") as file:
                file.write(data)
            os.chmod(temporary, mode)
            os.replace(temporary, path)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise
    except OSError as error:
        raise BadRequest(f"{path.name} could not be saved: {error.strerror}", 500) from None


def _version(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()[:16]


def _check_c(path: Path) -> dict:
    """Build the source as a robot run of it would (the build cache); the compiler's words
    as diagnostics with file names relative to the source's folder."""
    try:
        _, said = sources.executable_for(path)
        ok = True
    except sources.BuildError as error:
        said, ok = str(error), False
    return {
        "ok": ok,
        "output": said,
        "diagnostics": [diagnostic(match) for match in DIAGNOSTIC.finditer(said)],
        "program": None,
    }


def _check_python(path: Path) -> dict:
    command = [sys.executable, "-m", "eyesim.programs.python_check", str(path)]
    try:
        result = subprocess.run(command, capture_output=True, text=True, errors="replace", timeout=CHECK_SECONDS)
        found = json.loads(result.stdout)
    except subprocess.TimeoutExpired:
        return {
            "ok": False,
            "output": f"checking took longer than {CHECK_SECONDS} s and was stopped",
            "diagnostics": [],
            "program": None,
        }
    except ValueError:  # the checker itself failed: what it said is the output
        return {"ok": False, "output": result.stderr or result.stdout, "diagnostics": [], "program": None}
    diagnostics = [dict(d, file=path.name) for d in found["diagnostics"]]
    output = "\n".join(f"{path.name}:{d['line']}: {d['kind']}: {d['message']}" for d in diagnostics)
    return {"ok": found["ok"], "output": output, "diagnostics": diagnostics, "program": None}
