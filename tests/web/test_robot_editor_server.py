"""The robot editor's routes: behind the viewer's access policy, and every bad request answered
with a status and a specific message while the simulator goes on."""

from __future__ import annotations

import aiohttp
import pytest
from support.scenes import arena
from support.viewer import run_async, viewer_simulation


@pytest.fixture
def server(tmp_path):
    with viewer_simulation(arena(), root=tmp_path) as (sim, port, viewer):
        yield sim, viewer, tmp_path


async def _call(base: str, method: str, path: str, body=None, headers=None, raw: bytes | None = None):
    async with aiohttp.ClientSession() as session:
        kwargs = {"data": raw} if raw is not None else {"json": body} if body is not None else {}
        async with session.request(
            method, base + "/robot-editor/api" + path, headers=headers or {}, **kwargs
        ) as response:
            kind = response.headers.get("Content-Type", "")
            return response.status, (await response.json()) if "json" in kind else await response.text()


def call(server, method, path, body=None, headers=None, raw=None):
    _, viewer, _ = server
    return run_async(_call(f"http://127.0.0.1:{viewer.port}", method, path, body, headers, raw))


def test_every_route_is_behind_the_access_policy(server):
    foreign = {"Origin": "http://evil.example"}
    for method, path in (
        ("GET", "/schema"),
        ("GET", "/sources"),
        ("POST", "/open"),
        ("POST", "/check"),
        ("POST", "/save"),
        ("POST", "/drive/start"),
        ("POST", "/drive/command"),
        ("GET", "/drive/state"),
        ("POST", "/drive/stop"),
        ("GET", "/mesh/preview"),
    ):
        status, text = call(server, method, path, {}, foreign)
        assert status == 403 and "foreign Origin" in text, (method, path)
    status, text = call(server, "GET", "/schema", headers={"Host": "attacker.example"})
    assert status == 403
    assert not list(server[2].iterdir())  # nothing was written


def test_the_schema_route_serves_the_published_robot_schema(server):
    from eyesim.scene.json_format import schema

    status, body = call(server, "GET", "/schema")
    assert status == 200 and body == schema("robot")


def test_bad_requests_get_specific_errors_and_the_simulation_goes_on(server):
    sim, _, root = server
    (root / "notes.txt").write_text("hello")
    cases = [
        ("POST", "/open", None, b"{not json", 400, "not valid JSON"),
        ("POST", "/open", [1, 2], None, 400, "expected a JSON object"),
        ("POST", "/open", {"source": "builtin:R2D2"}, None, 404, "no built-in robot 'R2D2': expected one of"),
        ("POST", "/open", {"source": "new:hovercraft"}, None, 400, "unknown drive 'hovercraft'"),
        ("POST", "/open", {"source": "file:notes.txt"}, None, 400, "expected a .robi or .json robot file"),
        ("POST", "/open", {"source": "file:missing.robi"}, None, 404, "no such file"),
        ("POST", "/open", {"source": 7}, None, 400, "source must be text, not 7"),
        ("POST", "/open", {"source": "S4"}, None, 400, "source must be builtin:<name>, file:<path> or new:<drive>"),
        ("POST", "/open", {"source": "builtin:S4", "extra": 1}, None, 400, "unknown field 'extra'"),
        ("POST", "/check", {"robot": "S4"}, None, 400, "robot must be an object, not 'S4'"),
        ("POST", "/save", {"robot": {}}, None, 400, "field 'path' is missing"),
        (
            "POST",
            "/save",
            {"robot": {"format": "eyesim.robot", "version": 1}, "path": "x.robi"},
            None,
            400,
            "missing required property 'name'",
        ),
        ("POST", "/drive/command", {"type": "vw", "v": 100, "w": 0}, None, 409, "no test drive is running"),
        ("GET", "/drive/state", None, None, 409, "no test drive is running"),
    ]
    for method, path, body, raw, status, message in cases:
        got, answer = call(server, method, path, body, raw=raw)
        assert got == status and message in answer["error"], (path, body, answer)
    time_before = sim.time
    status, opened = call(server, "POST", "/open", {"source": "builtin:S4"})
    assert status == 200
    status, _ = call(server, "POST", "/drive/start", {"robot": opened["robot"], "builtin": "S4"})
    assert status == 200
    for body, message in (
        ({"type": "vw", "v": "fast", "w": 0}, "vw: v must be a number, not 'fast'"),
        ({"type": "servo", "servo": 1, "position": 300}, "servo: position must be a number from 0 to 255"),
        ({"type": "motor", "motor": 9, "speed": 50}, "no motor 9 (motors: [1, 2])"),
        ({"type": "servo", "servo": 1, "position": 10}, "no servo 1 (servos: none)"),
        ({"type": "fly"}, "type must be one of 'vw', 'motor', 'servo', 'reset', not 'fly'"),
    ):
        got, answer = call(server, "POST", "/drive/command", body)
        assert got == 400 and message in answer["error"], (body, answer)
    status, state = call(server, "GET", "/drive/state")
    assert status == 200 and set(state["readings"]["psd"]) == {"1", "2", "3", "4"}
    assert call(server, "POST", "/drive/stop", {})[0] == 200
    assert call(server, "GET", "/drive/state")[0] == 409
    sim_alive = run_async(_wait_for_time(sim, time_before))
    assert sim_alive


async def _wait_for_time(sim, after: float) -> bool:
    import asyncio

    for _ in range(100):
        if sim.time > after:
            return True
        await asyncio.sleep(0.05)
    return False


def test_a_robot_saved_elsewhere_still_finds_its_model(server, tmp_path):
    _, _, root = server
    (root / "robots" / "meshes").mkdir(parents=True)
    (root / "copies").mkdir()
    (root / "robots" / "meshes" / "cube.obj").write_text(
        "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n"
    )
    (root / "robots" / "Box.robi").write_text("drive DIFFERENTIAL_DRIVE\nname Box\nmodel meshes/cube.obj\n")
    status, opened = call(server, "POST", "/open", {"source": "file:robots/Box.robi"})
    assert status == 200 and opened["robot"]["model"] == "meshes/cube.obj"
    robot = {key: opened[key] for key in ("robot", "origin", "builtin")}  # as the page sends it back
    status, checked = call(server, "POST", "/check", robot)
    assert status == 200 and checked["preview"]["scene"]["robots"][0]["mesh"] == "/robot-editor/api/mesh/preview"
    status, mesh = call(server, "GET", "/mesh/preview")
    assert status == 200 and mesh["parts"]
    status, saved = call(server, "POST", "/save", {**robot, "path": "copies/Box.robi"})
    assert status == 200 and saved["loads"], saved
    assert "model ../robots/meshes/cube.obj" in (root / "copies" / "Box.robi").read_text()
    assert not [p for p in saved["problems"] if "model" in p["message"]]


def test_previews_and_test_drives_give_back_their_descriptors(server):
    """Each check builds a preview simulation and each drive a scratch one: the ones replaced
    close their sockets and selector at once, not whenever the garbage collector runs."""
    import gc
    import os

    status, opened = call(server, "POST", "/open", {"source": "builtin:S4"})
    assert status == 200
    robot = {"robot": opened["robot"], "builtin": "S4"}
    gc.disable()  # what is left open must be closed by the editor, not collected
    try:
        call(server, "POST", "/check", robot)
        call(server, "POST", "/drive/start", robot)
        before = len(os.listdir("/proc/self/fd"))
        for _ in range(15):
            assert call(server, "POST", "/check", robot)[0] == 200
            assert call(server, "POST", "/drive/start", robot)[0] == 200
        after = len(os.listdir("/proc/self/fd"))
    finally:
        gc.enable()
        call(server, "POST", "/drive/stop", {})
    assert after - before < 5, (before, after)
