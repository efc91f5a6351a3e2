"""The viewer as the application: open a scene, edit it, undo, save (docs/viewer.md#scenes).

JSON routes under /scenes/ (behind the viewer's access checks like every route):

    GET  /scenes/files?q=words   scene files under the roots, the recent ones, the roots
    GET  /scenes/catalog         robot and object types, programs: what the editor can add
    GET  /scenes/state           the scene being edited: its items, undo/redo, file
    POST /scenes/open            {"root", "path"}: replace the running scene with that file
    POST /scenes/new             {"width", "height"}: an empty floor of that size (mm), to build on
    POST /scenes/edit            {"editing": true|false}: start or end editing
    POST /scenes/edit            {"op": ...}: one edit (eyesim/scene/editing.py)
    POST /scenes/undo, /redo
    POST /scenes/save            {"root", "path", "format": "sim"|"json", "overwrite": bool}

Every body is checked against its definition in interface/viewer.schema.json first
(route_bodies.py): a malformed one answers 400 naming the field. A scene that fails to load or an
edit the loader refuses answers 422 with the diagnostics (file:line) and leaves the running scene
as it was. Editing stops the programs and pauses the simulation; each edit rebuilds the world
from the edited description; ending the edit starts the scene's programs again and resumes if the
simulation was running before."""

from __future__ import annotations

import asyncio
import dataclasses
import json
import logging
from pathlib import Path

from aiohttp import web

from eyesim.scene import SceneError, World, builtins, load_scene
from eyesim.scene.editing import Draft, EditError, apply, make_way, placed_body, saved_files, set_floor, settled
from eyesim.scene.placement import footprint
from eyesim.web.recent_files import RecentFiles
from eyesim.web.route_bodies import BadBody, checked_body
from eyesim.web.scene_files import FileAccessError, SceneRoots
from eyesim.web.simulation_calls import on_simulation

log = logging.getLogger("eyesim.web")
MAX_UNDO = 200
MAX_BODY = 64 * 1024
NEW_FLOOR = 2000  # mm, each side of a new scene's floor
SWAP_TIMEOUT = 30.0  # s to wait for the simulation thread to build a new world


class SceneWorkspace:
    def __init__(self, sim, launcher, roots: SceneRoots, recent: RecentFiles | None = None):
        self.sim = sim
        self.launcher = launcher
        self.roots = roots
        self.draft = Draft.of_scene(sim.scene)
        self.undo_stack: list[Draft] = []
        self.redo_stack: list[Draft] = []
        self.recent = recent if recent is not None else RecentFiles()  # kept from run to run
        self.editing = False
        self.browse_at_start = False  # started with no scene: the page opens the scene browser
        self._paused_before = False
        self._lock = asyncio.Lock()  # one open/edit/save at a time

    def add_routes(self, app: web.Application) -> None:
        app.router.add_get("/scenes/files", self._files)
        app.router.add_get("/scenes/catalog", self._catalog)
        app.router.add_get("/scenes/state", self._state)
        app.router.add_post("/scenes/open", self._open)
        app.router.add_post("/scenes/new", self._new)
        app.router.add_post("/scenes/edit", self._edit)
        app.router.add_post("/scenes/undo", self._undo)
        app.router.add_post("/scenes/redo", self._redo)
        app.router.add_post("/scenes/save", self._save)

    # -- answers ------------------------------------------------------------------------------
    def state(self) -> dict:
        place = self.roots.place_of(self.draft.file)
        items = self.draft.items()
        # the size a robot or object takes on the floor is its type's (the scene running has them all)
        types = {"robots": self.sim.scene.robot_types, "objects": self.sim.scene.object_types}
        for kind, known in types.items():
            for item in items[kind]:
                if item["type"] in known:
                    item["footprint"] = list(footprint(known[item["type"]]))
        return {
            "editing": self.editing,
            "browse_at_start": self.browse_at_start,
            "file": str(self.draft.file),
            "place": {"root": place[0], "path": place[1]} if place else None,
            "can_undo": bool(self.undo_stack),
            "can_redo": bool(self.redo_stack),
            "items": items,
        }

    async def _files(self, request: web.Request) -> web.Response:
        query = request.query.get("q", "")[:200]
        files = await _in_thread(self.roots.scene_files, query)
        recent = [dict(zip(("root", "path"), place)) for place in map(self.roots.place_of, self.recent.paths) if place]
        return web.json_response({"roots": self.roots.describe(), "files": files, "recent": recent})

    async def _catalog(self, request: web.Request) -> web.Response:
        def catalog():
            return {
                "robots": builtins.robot_names(),
                "objects": builtins.object_names(),
                "robot_files": self.roots.robot_files(),
                "object_files": self.roots.object_files(),
                "programs": self.roots.program_files(),
            }

        return web.json_response(await _in_thread(catalog))

    async def _state(self, request: web.Request) -> web.Response:
        return web.json_response(self.state())

    async def _open(self, request: web.Request) -> web.Response:
        body = await _body(request)
        async with self._lock:
            path = self._locate(body)
            try:
                scene = await _in_thread(load_scene, path)
            except SceneError as error:
                return _refused(f"{path.name} cannot be opened", error.diagnostics)
            except OSError as error:
                return _refused(f"cannot read {path.name}: {error.strerror}")
            await self._replace(scene, start_programs=True)
            self.draft = Draft.of_scene(scene)
            self.undo_stack.clear()
            self.redo_stack.clear()
            if self.editing:  # the new scene runs as the old one did before editing
                self.editing = False
                paused = self._paused_before
                await self._on_sim(lambda sim: sim.clock.set_paused(paused, sim.time_us))
            self.browse_at_start = False
            self.recent.note(path)
            return web.json_response(dict(self.state(), warnings=[_diagnostic(d) for d in scene.warnings]))

    async def _new(self, request: web.Request) -> web.Response:
        body = await _body(request)
        async with self._lock:
            size = {"op": "new", "width": body.get("width", NEW_FLOOR), "height": body.get("height", NEW_FLOOR)}
            try:
                draft = set_floor(Draft(self._untitled(), World(str(self._untitled()))), size, None)
            except EditError as error:
                return _refused(str(error))
            await self._set_editing(True)
            self.undo_stack.clear()
            self.redo_stack.clear()
            return await self._take(draft, self.undo_stack, clear_redo=True, opened=True)

    def _untitled(self) -> Path:
        """Where a new scene resolves its references from: the first writable root."""
        folder = next((r.path for r in self.roots.roots if r.writable), Path.cwd())
        return folder / "untitled.sim"

    async def _edit(self, request: web.Request) -> web.Response:
        body = await _body(request)
        async with self._lock:
            if "op" not in body:  # {"editing": true|false}
                await self._set_editing(body["editing"])
                return web.json_response(self.state())
            try:
                draft = apply(self.draft, body, self._locate)
                draft, moved = await _in_thread(_made_way, draft, body)
            except EditError as error:
                answer = _refused(str(error))
            else:
                answer = await self._take(draft, self.undo_stack, clear_redo=True, moved=moved)
            if answer.status == 422 and body["op"] == "move":
                # a drag moved the body in the physics already: back to where the scene has it
                await self._replace(await _in_thread(self.draft.scene), start_programs=False, opened=False)
            return answer

    async def _undo(self, request: web.Request) -> web.Response:
        await _body(request)
        async with self._lock:
            if not self.undo_stack:
                return _refused("nothing to undo")
            return await self._take(self.undo_stack.pop(), self.redo_stack, clear_redo=False)

    async def _redo(self, request: web.Request) -> web.Response:
        await _body(request)
        async with self._lock:
            if not self.redo_stack:
                return _refused("nothing to redo")
            return await self._take(self.redo_stack.pop(), self.undo_stack, clear_redo=False)

    async def _save(self, request: web.Request) -> web.Response:
        body = await _body(request)
        async with self._lock:
            target = self._locate(body)
            as_json = body["format"] == "json"
            wanted = ".json" if as_json else ".sim"
            if not target.name.lower().endswith(wanted):
                target = target.with_name(target.name + wanted)
            draft = self._with_live_settings(self.draft)
            if draft.world_file is not None and self._root_of(draft.world_file) != self._root_of(target):
                draft = draft.with_own_world()  # saved beside the scene, not named in another root
            files = saved_files(draft, target, as_json)
            outside = [p for p in files if not self.roots.writable(p)]
            if outside:
                return _refused(f"{outside[0]} is not in a scene root that can be written to")
            try:
                existing = [p for p in files if p.exists()]
            except OSError as error:  # a name the file system refuses
                return _refused(f"cannot save there: {error.strerror}")
            if existing and body.get("overwrite") is not True:
                return web.json_response(
                    {
                        "error": f"{', '.join(p.name for p in existing)} already exist(s)",
                        "exists": [self._shown(p) for p in existing],
                    },
                    status=409,
                )
            try:
                for path, text in files.items():
                    path.parent.mkdir(parents=True, exist_ok=True)
                    path.write_text(text, encoding="utf-8")
            except OSError as error:
                return _refused(f"cannot write {error.filename}: {error.strerror}")
            try:
                self.draft = Draft.of_scene(await _in_thread(load_scene, target))  # now named as saved
            except SceneError as error:  # written, but not readable as written: say so, keep editing
                return _refused(f"{target.name} was written but does not load back", error.diagnostics)
            self.recent.note(target)
            return web.json_response(dict(self.state(), saved=[self._shown(p) for p in files]))

    # -- doing it -----------------------------------------------------------------------------
    async def _take(
        self, draft: Draft, stack: list[Draft], clear_redo: bool, opened: bool = False, moved: str = ""
    ) -> web.Response:
        """Make `draft` the scene (the current one goes onto `stack`), or refuse it. `opened`: a new
        scene rather than an edit of this one (a recording goes on in another file). `moved`: what
        the edit moved clear, for the page. Bodies the loader moved (off a wall drawn across them)
        stay where it put them, so that a saved scene loads as it is shown."""
        draft = self._with_live_settings(draft)
        try:
            scene = await _in_thread(draft.scene)
        except SceneError as error:
            return _refused("the edit makes a scene the loader refuses", error.diagnostics)
        draft = settled(draft, scene)
        if not self.editing:
            await self._set_editing(True)
        await self._replace(scene, start_programs=False, opened=opened)
        stack.append(self.draft)
        del stack[:-MAX_UNDO]
        if clear_redo:
            self.redo_stack.clear()
        self.draft = draft
        answer = dict(self.state(), warnings=[_diagnostic(d) for d in scene.warnings])
        return web.json_response(dict(answer, moved=moved) if moved else answer)

    async def _set_editing(self, editing: bool) -> None:
        if editing == self.editing:
            return
        if editing:
            self._paused_before = self.sim.clock.paused
            await _in_thread(self.launcher.stop_all, 1.0)
            await self._on_sim(lambda sim: (sim.shutdown_programs(), sim.clock.set_paused(True, sim.time_us)))
            self.editing = True
        else:
            self.editing = False
            self._start_programs()
            paused = self._paused_before
            await self._on_sim(lambda sim: sim.clock.set_paused(paused, sim.time_us))

    async def _replace(self, scene, start_programs: bool, opened: bool = True) -> None:
        await _in_thread(self.launcher.stop_all, 1.0)
        await self._on_sim(lambda sim: sim.replace_scene(scene, opened))
        if start_programs:
            self._start_programs()

    def _start_programs(self) -> None:
        for robot, placement in zip(self.sim.robots, self.sim.scene.robots):
            if placement.program:
                self.launcher.start(robot.id, placement.program)

    async def _on_sim(self, action) -> None:
        """Run action(sim) on the simulation thread and wait for it; its exception is raised here."""
        try:
            await asyncio.wait_for(on_simulation(self.sim, action), SWAP_TIMEOUT)
        except asyncio.TimeoutError:
            raise web.HTTPServiceUnavailable(text="the simulation did not answer in time") from None
        except Exception as error:  # noqa: BLE001 - the new scene could not be built
            log.error("viewer: the new scene could not be built: %s", error)
            raise web.HTTPUnprocessableEntity(
                text=json.dumps({"error": f"the physics cannot build this scene: {error}", "diagnostics": []}),
                content_type="application/json",
            ) from None

    def _locate(self, place: dict) -> Path:
        """The file a {"root", "path"} object (checked by the schema) names, confined to its root."""
        try:
            return self.roots.locate(place["root"], place["path"])
        except FileAccessError as error:
            raise web.HTTPForbidden(text=json.dumps({"error": str(error)}), content_type="application/json")

    def _with_live_settings(self, draft: Draft) -> Draft:
        """The draft with the settings the page's settings panel gave the running scene
        (program_control.py): they are not edits, so undo does not take them back."""
        return dataclasses.replace(draft, settings=self.sim.scene.settings)

    def _root_of(self, path: Path) -> int | None:
        place = self.roots.place_of(path)
        return place[0] if place else None

    def _shown(self, path: Path) -> dict:
        """Where a file under the roots is, as the page names it."""
        place = self.roots.place_of(path)
        if place is None:
            raise ValueError(f"{path} is outside the scene roots")  # callers pass files found under them
        root, relative = place
        return {"root": root, "path": relative}


def _made_way(draft: Draft, op: dict) -> tuple[Draft, str]:
    """The draft with the robot or object the edit put down moved clear (scene.editing.make_way)."""
    body = placed_body(draft, op)
    if body is None:
        return draft, ""
    try:
        scene = draft.scene()
    except SceneError:  # refused as it is: _take says why
        return draft, ""
    return make_way(draft, scene, *body)


async def _in_thread(function, *args):
    return await asyncio.get_running_loop().run_in_executor(None, function, *args)


async def _body(request: web.Request) -> dict:
    try:
        return await checked_body(request, MAX_BODY)
    except BadBody as error:
        text = json.dumps({"error": str(error)})
        if error.status == 413:
            raise web.HTTPRequestEntityTooLarge(
                MAX_BODY, request.content_length or MAX_BODY + 1, text=text, content_type="application/json"
            ) from None
        raise web.HTTPBadRequest(text=text, content_type="application/json") from None


def _refused(message: str, diagnostics=()) -> web.Response:
    return web.json_response({"error": message, "diagnostics": [_diagnostic(d) for d in diagnostics]}, status=422)


def _diagnostic(d) -> dict:
    return {
        "kind": d.kind,
        "file": d.location.file,
        "line": d.location.line,
        "column": d.location.column,
        "message": d.message,
        "text": str(d),
    }
