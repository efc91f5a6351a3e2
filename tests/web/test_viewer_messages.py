"""What a live simulator really sends to a browser follows interface/viewer.schema.json.

A scene with several robots (LCD, PSDs, lidar, camera, an arm, omni wheels), objects, the VIS and
TRACE settings and a loader warning; programs print on their LCDs, set menus, take camera images
and lidar scans, send serial bytes, beep and drive digital lines; a browser connects, goes back
over the timeline, asks for signals, series and paths, follows the present again, resets the world
and sends a bad command. Every message it gets in those seconds is checked against the schema."""

from __future__ import annotations

import asyncio
import json
import sys

import aiohttp
import pytest
from support.client import ProgramClient, RemoteError
from support.viewer import run_async, viewer_simulation

from eyesim.protocol.channel_schema import command_problem, server_message_problems
from eyesim.scene import builtins, load_scene
from eyesim.paths import EXAMPLES_DIR

EXAMPLES = EXAMPLES_DIR
EVERY_KIND = {
    "scene",
    "snapshot",
    "status",
    "timeline",
    "lcd",
    "camera",
    "menu",
    "console",
    "program",
    "audio",
    "serial",
    "io",
    "frame",
    "signals",
    "series",
    "paths",
    "error",
}


@pytest.fixture
def busy_scene(tmp_path):
    mecanum = tmp_path / "Mecanum.robi"  # with a line the loader warns about (the scene's `warnings`)
    mecanum.write_text((builtins.ROBOTS_DIR / "Mecanum.robi").read_text() + "\nfrobnicate 1 2\n")
    scene = tmp_path / "busy.sim"
    scene.write_text(
        f"world {EXAMPLES / 'scenes' / 'land.wld'}\nsettings VIS TRACE\n"
        f"robi {builtins.ROBOTS_DIR / 'Reacher.robi'}\nrobi {mecanum}\n"
        "S4 500 500 0\nS4 1500 500 90\nReacher 1500 1500 0\nMecanum 2400 1900 0\n"
        "Can 1000 1000 0\nCrate 900 2600 0\n"
    )
    return load_scene(str(scene))


def busy_programs(port: int) -> list[ProgramClient]:
    """Two programs that use everything a robot panel shows."""
    programs = []
    for robot, name in ((1, "alpha"), (2, "beta")):
        program = ProgramClient(port)
        program.hello(str(robot), name)
        program.call("LCD_PRINTF", f"robot {robot} here\n")
        program.call("LCD_MENU", "Go", "", "Stop", "End")
        program.call("CAM_INIT", 1)  # QVGA
        program.call("CAM_GET")
        program.call("LIDAR_GET")
        program.call("PSD_GET", 1)
        program.call("AU_BEEP")
        for call in (
            ("SER_INIT", 1, 115200, 0),
            ("SER_SEND", 1, b"hello\n\xff"),
            ("DIGITAL_SETUP", 1, ord("o")),
            ("DIGITAL_WRITE", 1, 1),
        ):
            try:
                program.call(*call)
            except RemoteError as error:  # the message still has to be right; the call is not the point
                print(f"{call[0]}: {error}", file=sys.stderr)
        programs.append(program)
    return programs


async def until(condition, what: str, limit: float = 60.0) -> None:
    """Wait for the browser to have received something (a generous limit for a loaded machine)."""
    loop = asyncio.get_running_loop()
    deadline = loop.time() + limit
    while not condition():
        assert loop.time() < deadline, f"the browser never got {what}"
        await asyncio.sleep(0.02)


async def watch(port: int, program_port: int, sim) -> list[dict]:
    """Everything one browser gets while programs run and it uses the timeline, resets and errs."""
    received: list[dict] = []

    def kinds() -> set[str]:
        return {message["type"] for message in received}

    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(f"ws://127.0.0.1:{port}/ws", max_msg_size=0) as ws:

            async def listen():
                async for message in ws:
                    assert message.type == aiohttp.WSMsgType.TEXT, message
                    received.append(json.loads(message.data))

            listener = asyncio.get_running_loop().create_task(listen())
            await until(lambda: {"scene", "snapshot", "status"} <= kinds(), "the scene and a snapshot")
            programs = await asyncio.to_thread(busy_programs, program_port)
            sim.call(lambda s: s.events.program(1, "started", "alpha", None))
            sim.call(lambda s: s.events.console(1, "stdout", "robot 1 says hello\n"))
            sim.call(lambda s: s.events.console(2, "stderr", "x" * 60_000))  # cut to the panel's 50,000
            sim.call(lambda s: s.events.program(2, "exited", "beta", 3))
            for command in (
                {"type": "seek", "time": 0.1},
                {"type": "seek", "time": 1e9},
                {"type": "signals"},
                {"type": "paths"},
                {"type": "live"},
                {"type": "key", "robot": 1, "key": 3},
            ):
                await ws.send_str(json.dumps(command))
            await until(lambda: EVERY_KIND - {"series"} <= kinds(), "what programs and commands cause")
            signals = next(m for m in received if m["type"] == "signals")["signals"]
            await ws.send_str(json.dumps({"type": "series", "ids": [s["id"] for s in signals[:3]]}))
            await ws.send_str(json.dumps({"type": "reset"}))
            await until(
                lambda: "series" in kinds() and sum(m["type"] == "scene" for m in received) == 2,
                "the series and the scene after the reset",
            )
            listener.cancel()
            for program in programs:
                program.close()
    return received


def test_every_message_a_live_simulator_sends_follows_the_schema(busy_scene):
    with viewer_simulation(busy_scene) as (sim, port, server):
        received = run_async(watch(server.port, port, sim))
    kinds = {message["type"] for message in received}
    assert EVERY_KIND <= kinds, kinds
    assert sum(m["type"] == "scene" for m in received) == 2  # on connect and after the reset
    first_scene = next(m for m in received if m["type"] == "scene")
    assert first_scene["warnings"] and first_scene["objects"] and first_scene["bodies"]
    assert any(m.get("rays") for m in received if m["type"] == "snapshot")
    kinds_in_frames = {inner["type"] for m in received if m["type"] == "frame" for inner in m["messages"]}
    assert {"snapshot", "lcd", "menu"} <= kinds_in_frames, kinds_in_frames
    problems = {}
    for message in received:
        for problem in server_message_problems(message):
            problems.setdefault(problem, message["type"])
    assert problems == {}


def test_the_schema_refuses_what_the_server_must_not_send():
    """The check itself can fail: wrong types, ranges, missing and unknown fields are found."""
    good = {"type": "lcd", "robot": 1, "png": "iVBORw0KGgo="}
    assert server_message_problems(good) == []
    assert server_message_problems({**good, "png": "not base64!"})
    assert server_message_problems({**good, "robot": 0})
    assert server_message_problems({"type": "lcd", "robot": 1})
    assert server_message_problems({**good, "extra": 1})
    assert server_message_problems({"type": "mystery"})
    assert command_problem({"type": "key", "robot": 1, "key": 2}) is None
