"""The viewer channel's robot I/O (docs/viewer-channel.md): a C program reads what a browser sets —
an analog channel, an IR code, a touch, serial input, a digital line — and the browser gets the
program's digital output, serial output and beep."""

import asyncio
import json
import os
import subprocess
import time

import aiohttp
import pytest
from support.programs import build
from support.scenes import arena
from support.simulator import token_for
from support.viewer import run_async, viewer_simulation


@pytest.fixture
def viewer_sim():
    with viewer_simulation(arena()) as (sim, port, server):
        yield port, server


async def browser_session(url: str, program: subprocess.Popen) -> list[dict]:
    messages = []
    async with aiohttp.ClientSession() as session, session.ws_connect(url) as ws:
        assert (await asyncio.to_thread(program.stdout.readline)).strip() == "ready"
        for command in [
            {"type": "analog", "robot": 1, "channel": 4, "value": 321},
            {"type": "irtv", "robot": 1, "code": "OK"},
            {"type": "touch", "robot": 1, "x": 123, "y": 45},
            {"type": "serial", "robot": 1, "interface": 0, "text": "Z"},
            {"type": "digital", "robot": 1, "line": 1, "level": 1},
        ]:
            await ws.send_str(json.dumps(command))
        deadline = time.monotonic() + 20

        def seen(kind, test=lambda m: True):
            return any(m["type"] == kind and m["robot"] == 1 and test(m) for m in messages)

        while not (
            seen("serial", lambda m: m["text"] == "reply\n")
            and seen("audio")
            and seen("io", lambda m: m["digital"][15]["level"] == 1)
        ):
            received = await ws.receive(timeout=deadline - time.monotonic())
            messages.append(json.loads(received.data))
    return messages


def test_a_program_reads_what_the_browser_sets_and_the_browser_sees_its_answers(tmp_path, viewer_sim):
    port, server = viewer_sim
    executable = build("viewer_io", tmp_path, "-Wall", "-Wextra", "-Werror")
    program = subprocess.Popen(
        [str(executable)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=dict(os.environ, EYESIM_PORT=str(port), EYESIM_ROBOT="1", EYESIM_TOKEN=token_for(port)),
    )
    try:
        messages = run_async(browser_session(f"ws://127.0.0.1:{server.port}/ws", program))
        out, err = program.communicate(timeout=20)
    finally:
        program.kill()
    assert program.returncode == 0, err
    assert out.strip() == "analog 321 irtv O touch 123,45 serial Z"
    io = [m for m in messages if m["type"] == "io"][-1]
    assert io["digital"][0] == {"direction": "i", "level": 1, "driven": 1}
    assert io["digital"][15] == {"direction": "o", "level": 1, "driven": None}
    assert io["analog"] == [0, 0, 0, 321, 0, 0, 0, 512]
    beep = next(m for m in messages if m["type"] == "audio")
    assert beep["sound"] == "beep" and beep["duration"] == 0.2
    errors = [m for m in messages if m["type"] == "error"]
    assert errors == []


def test_bad_robot_io_commands_get_an_error_each(viewer_sim):
    _port, server = viewer_sim
    bad = [
        ({"type": "touch", "robot": 1, "x": 480, "y": 0}, "touch: x must be a whole number from 0 to 479, not 480"),
        ({"type": "touch", "robot": 9, "x": 1, "y": 1}, "touch: no robot 9"),
        ({"type": "irtv", "robot": 1, "code": "PLAY"}, "'PLAY' is not an IR remote button"),
        (
            {"type": "serial", "robot": 1, "interface": 0, "text": "\u20ac"},
            "text must be bytes as characters U+0000..U+00FF",
        ),
        (
            {"type": "serial", "robot": 1, "interface": 21, "text": "x"},
            "interface must be a whole number from 0 to 20, not 21",
        ),
        ({"type": "digital", "robot": 1, "line": 0, "level": 1}, "line must be a whole number from 1 to 16, not 0"),
        ({"type": "digital", "robot": 1, "line": 1, "level": 2}, "level must be one of 0, 1, null, not 2"),
        (
            {"type": "analog", "robot": 1, "channel": 1, "value": 1024},
            "value must be a whole number from 0 to 1023, not 1024",
        ),
    ]

    async def send_all():
        errors = []
        async with aiohttp.ClientSession() as session, session.ws_connect(f"ws://127.0.0.1:{server.port}/ws") as ws:
            for command, _ in bad:
                await ws.send_str(json.dumps(command))
            while len(errors) < len(bad):
                message = json.loads((await ws.receive(timeout=10)).data)
                if message["type"] == "error":
                    errors.append(message["message"])
        return errors

    errors = run_async(send_all())
    for (command, expected), error in zip(bad, errors):
        assert expected in error, (command, error)
