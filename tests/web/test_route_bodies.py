"""The JSON bodies of the HTTP routes follow interface/viewer.schema.json (`routes`).

A real `eyesim run` with a scene of a robot with an .obj model, a compiled program and a broken
scene beside it: every route is used as the page uses it (programs, settings, the robot editor
and its test drive, the scene browser and editor), and every answer, refusals included, is
checked against the schema; every route answered at least once. Malformed bodies get 400 with a
sentence naming the field, and the simulator goes on as it was."""

from __future__ import annotations

import json
import sys
import urllib.error
import urllib.request
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402
from support.scenes import arena  # noqa: E402
from support.simulator import running_simulation  # noqa: E402

from eyesim.web.io_thread import IoThread  # noqa: E402
from eyesim.programs.launcher import Launcher  # noqa: E402
from eyesim.protocol.channel_schema import ROUTES, route_answer_problems  # noqa: E402
from eyesim.web.scene_files import SceneRoots  # noqa: E402
from eyesim.web.scene_workspace import SceneWorkspace  # noqa: E402
from eyesim.web.server import ViewerServer  # noqa: E402

WAIT_FOREVER = '#include "eyebot.h"\nint main(void) { for (;;) OSWait(100); }\n'
CUBE = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n"
NOT_JSON_ROUTES = {"GET /ws", "GET /scene/floor-texture", "GET /{path}"}  # WebSocket, image, page files


@pytest.fixture(scope="module")
def simulator(tmp_path_factory):
    folder = tmp_path_factory.mktemp("routes")
    (folder / "robots" / "meshes").mkdir(parents=True)
    (folder / "robots" / "meshes" / "cube.obj").write_text(CUBE)
    (folder / "robots" / "Box.robi").write_text("drive DIFFERENTIAL_DRIVE\nname Box\nmodel meshes/cube.obj\n")
    (folder / "scene.sim").write_text("robi robots/Box.robi\nBox 500 500 0\nS4 1200 800 90\nCan 1000 1000 0\n")
    (folder / "broken.sim").write_text("S4 100 100 0\nTeapot 300 300 0\n")
    (folder / "wait.c").write_text(WAIT_FOREVER)
    with simulator_with_viewer("scene.sim", cwd=folder) as (process, url):
        yield url.split("?")[0].rstrip("/"), folder


class Checked:
    """Calls routes and checks every answer against the schema."""

    def __init__(self, url: str):
        self.url = url
        self.answered: set[str] = set()  # routes that answered 2xx

    def __call__(self, route: str, body=None, status: int = 200, path: str | None = None, raw: bytes | None = None):
        method, pattern = route.split(" ")
        data = raw if raw is not None else None if method == "GET" else json.dumps(body).encode()
        request = urllib.request.Request(
            self.url + (path or pattern), data=data, method=method, headers={"Content-Type": "application/json"}
        )
        try:
            with urllib.request.urlopen(request, timeout=120) as response:
                got, answer = response.status, json.load(response)
        except urllib.error.HTTPError as error:
            got, answer = error.code, json.loads(error.read().decode())
        assert got == status, (route, body, got, answer)
        assert route_answer_problems(route, got, answer) == [], (route, answer)
        if got < 300:
            self.answered.add(route)
        return answer


def test_every_route_answers_what_the_schema_says(simulator):
    url, folder = simulator
    call = Checked(url)
    # Programs and settings.
    assert call("POST /api/programs/compile", {"root": 0, "path": "wait.c"})["ok"]
    overview = call("GET /api/programs")
    assert {"root": 0, "path": "wait", "kind": "executable"} in overview["files"]
    assert call("POST /api/programs/start", {"robot": 2, "root": 0, "path": "wait"})["state"] == "running"
    assert call("POST /api/programs/restart", {"robot": 2})["state"] == "running"
    assert call("POST /api/programs/stop", {"robot": 2})["state"] == "stopped"
    assert call("POST /api/programs/stop", {"robot": 2}, status=400)["error"] == "robot 2 runs no program"
    # The program editor: the executable's source beside it, saved, checked and run.
    source = call("POST /api/sources/robot", {"robot": 2})
    assert (source["path"], source["kind"]) == ("wait.c", "c")
    assert call("POST /api/sources/read", {"root": 0, "path": "wait.c"})["text"] == WAIT_FOREVER
    call("POST /api/sources/save", {"root": 0, "path": "wait.c", "text": WAIT_FOREVER, "version": source["version"]})
    assert call("POST /api/sources/check", {"root": 0, "path": "wait.c"})["ok"]
    assert call("POST /api/sources/run", {"robot": 2, "root": 0, "path": "wait.c"})["state"] == "running"
    assert call("POST /api/programs/stop", {"robot": 2})["state"] == "stopped"
    assert call("GET /api/settings")["vis"] is False
    assert call("POST /api/settings", {"vis": True, "psd_noise": 2.5, "seed": 4})["psd_noise"] == 2.5
    # The robot editor, its preview and its test drive.
    assert call("GET /robot-editor/api/schema")["title"]
    assert "robots/Box.robi" in call("GET /robot-editor/api/sources")["files"]
    opened = call("POST /robot-editor/api/open", {"source": "file:robots/Box.robi"})
    robot = {key: opened[key] for key in ("robot", "origin", "builtin")}
    assert call("POST /robot-editor/api/check", robot)["preview"]["scene"]["robots"][0]["mesh"]
    assert call("GET /robot-editor/api/mesh/{which}", path="/robot-editor/api/mesh/preview")["parts"]
    assert call("POST /robot-editor/api/save", {**robot, "path": "robots/Box2.robi"})["loads"]
    call("POST /robot-editor/api/save", {**robot, "path": "robots/Box2.robi"}, status=409)
    s4 = call("POST /robot-editor/api/open", {"source": "builtin:S4"})
    call("POST /robot-editor/api/drive/start", {"robot": s4["robot"], "builtin": "S4"})
    assert call("POST /robot-editor/api/drive/command", {"type": "vw", "v": 200, "w": 10}) == {"ok": True}
    call("POST /robot-editor/api/drive/command", {"type": "motor", "motor": 1, "speed": 30})
    call("POST /robot-editor/api/drive/command", {"type": "servo", "servo": 1, "position": 5}, status=400)
    call("POST /robot-editor/api/drive/command", {"type": "reset"})
    state = call("GET /robot-editor/api/drive/state")
    assert set(state["readings"]["psd"]) == {"1", "2", "3", "4"} and state["readings"]["camera"]
    call("POST /robot-editor/api/drive/stop", {})
    call("GET /robot-editor/api/drive/state", status=409)
    # The running scene's robot model.
    assert call("GET /scene/mesh/{kind}/{id}", path="/scene/mesh/robot/1")["parts"]
    # The scene browser and editor.
    files = call("GET /scenes/files", path="/scenes/files?q=sim")
    assert {"root": 0, "path": "broken.sim"} in files["files"]
    catalog = call("GET /scenes/catalog")
    assert "S4" in catalog["robots"] and {"root": 0, "path": "wait"} in catalog["programs"]
    assert call("GET /scenes/state")["items"]["robots"][0]["type"] == "Box"
    assert call("POST /scenes/edit", {"editing": True})["editing"]
    for edit in (
        {"op": "add-robot", "type": "S4", "x": 300, "y": 1500, "phi": 45},
        {"op": "add-object", "type": "Can", "x": 600, "y": 1500},
        {"op": "add-marker", "x": 700, "y": 300, "color": [0, 0, 255]},
        {"op": "add-wall", "x1": 100, "y1": 100, "x2": 100, "y2": 900},
        {"op": "move", "kind": "robot", "index": 0, "x": 400, "y": 400, "phi": 90},
        {"op": "move", "kind": "wall", "index": 0, "x1": 150, "y1": 100, "x2": 150, "y2": 900},
        {"op": "duplicate", "kind": "object", "index": 0},
        {"op": "delete", "kind": "marker", "index": 0},
        {"op": "set-floor", "width": 3000, "height": 2500},
        {"op": "set-program", "index": 1, "program": {"root": 0, "path": "wait"}},
    ):
        state = call("POST /scenes/edit", edit)
    assert state["items"]["floor"] == {"width": 3000, "height": 2500}
    call("POST /scenes/edit", {"op": "move", "kind": "robot", "index": 9, "x": 1, "y": 1}, status=422)
    assert call("POST /scenes/undo", {})["can_redo"]
    assert call("POST /scenes/redo", {})["items"]["robots"][1]["program"] == str((folder / "wait").resolve())
    saved = call("POST /scenes/save", {"root": 0, "path": "edited", "format": "sim"})["saved"]
    assert {"root": 0, "path": "edited.sim"} in saved
    refused = call("POST /scenes/save", {"root": 0, "path": "edited.sim", "format": "sim"}, status=409)
    assert {"root": 0, "path": "edited.sim"} in refused["exists"]
    call("POST /scenes/save", {"root": 0, "path": "edited.json", "format": "json", "overwrite": True})
    assert not call("POST /scenes/edit", {"editing": False})["editing"]
    assert call("POST /scenes/open", {"root": 0, "path": "broken.sim"}, status=422)["diagnostics"]
    assert call("POST /scenes/open", {"root": 0, "path": "edited.sim"})["place"] == {"root": 0, "path": "edited.sim"}
    assert call("POST /scenes/new", {"width": 1500})["items"]["floor"] == {"width": 1500, "height": 2000}
    assert call.answered == set(ROUTES), f"routes never answered: {sorted(set(ROUTES) - call.answered)}"


BAD_BODIES = [
    ("POST /scenes/open", {"root": 0}, "field 'path' is missing"),
    ("POST /scenes/open", {"root": "0", "path": "a.sim"}, "root must be a whole number, not '0'"),
    ("POST /scenes/new", {"width": 5}, "width must be a number from 100 to 100000, not 5"),
    (
        "POST /scenes/edit",
        {"op": "move", "kind": "robot", "index": 0, "x": "left", "y": 0},
        "move: x must be a number, not 'left'",
    ),
    ("POST /scenes/edit", {"op": "teleport"}, "op must be one of 'add-robot', "),
    ("POST /scenes/edit", {"editing": 1}, "editing must be true or false, not 1"),
    ("POST /scenes/undo", {"steps": 2}, "unknown field 'steps'"),
    ("POST /scenes/redo", [], "expected a JSON object"),
    ("POST /scenes/save", {"root": 0, "path": "a", "format": "xml"}, "format must be one of 'sim', 'json', not 'xml'"),
    ("POST /api/programs/start", {"robot": 0, "root": 0, "path": "wait"}, "robot must be a whole number from 1 to"),
    ("POST /api/programs/stop", {}, "field 'robot' is missing"),
    ("POST /api/programs/restart", {"robot": True}, "robot must be a whole number, not True"),
    ("POST /api/programs/compile", {"root": 0, "path": 5}, "path must be text, not 5"),
    ("POST /api/sources/robot", {"robot": "1"}, "robot must be a whole number, not '1'"),
    ("POST /api/sources/read", {"root": 0}, "field 'path' is missing"),
    ("POST /api/sources/save", {"root": 0, "path": "wait.c"}, "field 'text' is missing"),
    ("POST /api/sources/check", {"root": 0, "path": ""}, "path must have at least 1 characters"),
    ("POST /api/sources/run", {"robot": 1, "root": 0}, "field 'path' is missing"),
    ("POST /api/settings", {"psd_noise": "lots"}, "psd_noise must be a number, not 'lots'"),
    ("POST /api/settings", {"gravity": 1}, "unknown field 'gravity' (fields: vis, trace, psd_noise, seed)"),
    ("POST /robot-editor/api/open", {"source": 1}, "source must be text, not 1"),
    ("POST /robot-editor/api/check", {}, "field 'robot' is missing"),
    (
        "POST /robot-editor/api/save",
        {"robot": {}, "path": "x.robi", "overwrite": "yes"},
        "overwrite must be true or false, not 'yes'",
    ),
    ("POST /robot-editor/api/drive/start", {"robot": []}, "robot must be an object, not []"),
    (
        "POST /robot-editor/api/drive/command",
        {"type": "motor", "motor": 0, "speed": 10},
        "motor: motor must be a whole number from 1 to 64, not 0",
    ),
    ("POST /robot-editor/api/drive/stop", {"now": True}, "unknown field 'now'"),
]


def test_malformed_bodies_get_400_naming_the_field(simulator):
    url, _ = simulator
    call = Checked(url)
    before = call("GET /scenes/state")
    for route, body, sentence in BAD_BODIES:
        assert sentence in call(route, body, status=400)["error"], (route, body)
    posts = {route for route in ROUTES if route.startswith("POST")}
    assert posts == {route for route, _, _ in BAD_BODIES}, "every POST route has a malformed body here"
    for raw, sentence in (
        (b"{not json", "not valid JSON"),
        (b'{"root": NaN, "path": "a"}', "NaN is not a JSON number"),
        (b"[" * 5000, "not valid JSON"),
    ):
        assert sentence in call("POST /scenes/open", raw=raw, status=400)["error"]
    assert "larger than" in call("POST /api/settings", raw=b" " * 70_000, status=413)["error"]
    assert call("GET /scenes/state") == before  # nothing changed


def test_every_json_route_the_server_serves_is_in_the_schema(tmp_path):
    with running_simulation(arena()) as (sim, port):
        io = IoThread()
        io.start()
        launcher = Launcher(sim, "127.0.0.1", port)
        viewer = ViewerServer(sim, io, "127.0.0.1", 0, launcher=launcher, run_folder=tmp_path, require_token=False)
        viewer.workspace = SceneWorkspace(sim, launcher, SceneRoots([("work", tmp_path, True)]))
        viewer.start()
        try:
            served = {
                f"{route.method} {route.resource.canonical}"
                for route in viewer._runner.app.router.routes()
                if route.method in ("GET", "POST")
            }
        finally:
            viewer.stop()
            io.stop()
    assert served - NOT_JSON_ROUTES == set(ROUTES)


def test_a_file_name_too_long_for_the_file_system_is_refused_with_a_reason(simulator):
    """It used to answer 500 with a traceback: a name longer than the file system's 255 bytes."""
    url, folder = simulator
    call = Checked(url)
    refused = call("POST /scenes/save", {"root": 0, "path": "x" * 300, "format": "sim"}, status=403)
    assert "a folder or file name of 300 bytes, more than 250" in refused["error"]
    refused = call("POST /scenes/save", {"root": 0, "path": "deep/" + "y" * 254, "format": "json"}, status=403)
    assert "more than 250" in refused["error"]
    assert call("POST /scenes/save", {"root": 0, "path": "z" * 250, "format": "sim"})["saved"]
