"""The browser's `place` command (drag to place): validation and effect; and the scene warnings the viewer gets."""

import json
import math
import sys
import time
from pathlib import Path

import aiohttp
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.client import ProgramClient  # noqa: E402
from support.viewer import run_async, viewer_simulation  # noqa: E402
from support.worlds import arena_scene, example_robot  # noqa: E402

from eyesim.scene import load_scene  # noqa: E402


@pytest.fixture(scope="module")
def viewer_sim():
    scene = arena_scene(
        robots=[("S4", (500, 500, 0)), (example_robot("Reacher"), (2500, 2500, 0))],
        objects=[("Can", (1500, 500, 0)), ("Crate1", (2500, 500, 0))],
    )
    with viewer_simulation(scene) as running:
        yield running


async def _talk(port: int, send: list[dict], until, timeout: float = 20.0) -> list[dict]:
    """Sends `send` on a viewer socket and collects what comes back until `until(messages)` holds."""
    messages = []
    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(f"ws://127.0.0.1:{port}/ws") as ws:
            for message in send:
                await ws.send_str(json.dumps(message))
            deadline = time.monotonic() + timeout
            while not until(messages):
                remaining = deadline - time.monotonic()
                assert remaining > 0, f"gave up waiting; got types {[m['type'] for m in messages][-20:]}"
                messages.append(json.loads((await ws.receive(timeout=remaining)).data))
    return messages


def _pose_in(snapshot: dict, kind: str, ident: int) -> dict:
    return next(entry for entry in snapshot[kind] if entry["id"] == ident)


def _yaw(quat) -> float:
    w, x, y, z = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def test_bad_place_commands_get_clear_errors_and_move_nothing(viewer_sim):
    _, port, server = viewer_sim
    bad = [
        ({"type": "place", "robot": 9, "x": 1, "y": 1, "phi": 0}, "no robot 9"),
        ({"type": "place", "object": 7, "x": 1, "y": 1, "phi": 0}, "no object 7"),
        ({"type": "place", "robot": "1", "x": 1, "y": 1, "phi": 0}, "robot must be a whole number, not '1'"),
        ({"type": "place", "x": 1, "y": 1, "phi": 0}, "either 'robot' or 'object'"),
        ({"type": "place", "robot": 1, "object": 1, "x": 1, "y": 1, "phi": 0}, "either 'robot' or 'object'"),
        ({"type": "place", "robot": 1, "x": "1", "y": 1, "phi": 0}, "x must be a number, not '1'"),
        ({"type": "place", "robot": 1, "x": 1, "y": True, "phi": 0}, "y must be a number, not True"),
        ({"type": "place", "robot": 1, "x": 1, "y": 1}, "field 'phi' is missing"),
        # NaN is not JSON, but Python's json writes it: refused all the same, as not valid JSON.
        ({"type": "place", "robot": 1, "x": float("nan"), "y": 1, "phi": 0}, "not valid JSON: NaN"),
        ({"type": "place", "robot": 1, "x": 3.5, "y": 1, "phi": 0}, "off the floor"),
        ({"type": "place", "object": 1, "x": 1, "y": -0.01, "phi": 0}, "off the floor"),
        ({"type": "place", "robot": 2, "x": 1, "y": 1, "phi": 0}, "mounted on the floor"),
        ({"type": "place", "object": 2, "x": 1, "y": 1, "phi": 0}, "is fixed"),
    ]
    messages = run_async(
        _talk(
            server.port, [message for message, _ in bad], lambda ms: sum(m["type"] == "error" for m in ms) == len(bad)
        )
    )
    errors = [m["message"] for m in messages if m["type"] == "error"]
    for (_, expected), error in zip(bad, errors):
        assert expected in error and (error.startswith("place: ") or expected.startswith("not valid JSON"))
    program = ProgramClient(port)
    program.hello()
    x, y, _, phi = program.call("SIM_GET_ROBOT", 1)[1:]
    assert abs(x - 500) <= 2 and abs(y - 500) <= 2 and abs(phi) <= 1
    assert program.call("SIM_GET_OBJECT", 1)[1:3] == (1500, 500)
    program.close()


def test_placing_a_robot_moves_its_true_pose_not_its_odometry_even_while_paused(viewer_sim):
    sim, port, server = viewer_sim
    program = ProgramClient(port)
    assert program.hello()[1] == 1
    assert program.call("VW_GET_POSITION")[:3] == (0, 0, 0)
    place = {"type": "place", "robot": 1, "x": 1.2, "y": 0.8, "phi": math.pi / 2}

    def moved(messages):
        snapshots = [m for m in messages if m["type"] == "snapshot"]
        return snapshots and abs(_pose_in(snapshots[-1], "robots", 1)["pos"][0] - 1.2) < 1e-3

    messages = run_async(_talk(server.port, [{"type": "pause"}, place], moved))
    snapshot = [m for m in messages if m["type"] == "snapshot"][-1]
    pose = _pose_in(snapshot, "robots", 1)
    assert pose["pos"][1] == pytest.approx(0.8, abs=1e-3)
    assert _yaw(pose["quat"]) == pytest.approx(math.pi / 2, abs=1e-3)
    assert sim.clock.paused
    paused_at = snapshot["time"]
    # Asked while paused; the replies come once simulation time goes on (each call takes the call time).
    true_pose, odometry = program.send("SIM_GET_ROBOT", 1), program.send("VW_GET_POSITION")
    assert sim.time == paused_at  # placing while paused took no simulation time

    run_async(
        _talk(server.port, [{"type": "resume"}], lambda ms: any(m["type"] == "status" and not m["paused"] for m in ms))
    )
    assert program.reply("SIM_GET_ROBOT", true_pose)[1:] == (1200, 800, 0, 90)
    assert program.reply("VW_GET_POSITION", odometry)[:3] == (0, 0, 0)  # odometry did not notice
    program.close()


def test_placing_an_object_sets_it_down_upright_at_the_new_place(viewer_sim):
    _, port, server = viewer_sim
    run_async(
        _talk(
            server.port,
            [{"type": "place", "object": 1, "x": 0.9, "y": 1.7, "phi": -1.0}],
            lambda ms: any(
                m["type"] == "snapshot" and abs(_pose_in(m, "objects", 1)["pos"][0] - 0.9) < 1e-3 for m in ms
            ),
        )
    )
    program = ProgramClient(port)
    program.hello()
    x, y, z, phi = program.call("SIM_GET_OBJECT", 1)[1:]
    assert (x, y, phi) == (900, 1700, -57) and abs(z) <= 2
    program.close()


def test_the_scene_message_lists_the_loaders_warnings(tmp_path):
    (tmp_path / "room.wld").write_text("floor 2000 2000\nwobble 3\n0 0 2000 0\n")
    (tmp_path / "room.sim").write_text("world room.wld\nS4 500 500 0\n")
    scene = load_scene(str(tmp_path / "room.sim"))
    with viewer_simulation(scene) as (_, _, server):
        messages = run_async(_talk(server.port, [], lambda ms: ms and ms[0]["type"] == "scene"))
    (warning,) = messages[0]["warnings"]
    assert warning["file"] == str(tmp_path / "room.wld") and warning["line"] == 2
    assert warning["code"] == "unknown-keyword" and "unknown keyword 'wobble'" in warning["message"]
