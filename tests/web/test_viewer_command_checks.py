"""Browser commands are checked against interface/viewer.schema.json before anything acts on them:
each wrong one gets one sentence naming the field, and every command the schema lists is handled."""

from __future__ import annotations

import json

import aiohttp
import pytest
from support.scenes import arena
from support.viewer import run_async, viewer_simulation

from eyesim.protocol.channel_schema import command_problem, command_validators
from eyesim.protocol.channel_schema import SCHEMA


@pytest.mark.parametrize(
    "command, problem",
    [
        ({"type": "warp"}, "unknown message type 'warp'"),
        ([1, 2], "expected a JSON object with a 'type'"),
        ({"type": 7}, "unknown message type 7"),
        ({"type": "key", "robot": 1, "key": 3}, "key: key must be one of 1, 2, 4, 8, not 3"),
        ({"type": "key", "robot": "1", "key": 1}, "key: robot must be a whole number, not '1'"),
        ({"type": "key", "robot": True, "key": 1}, "key: robot must be a whole number, not True"),
        (
            {"type": "key", "robot": 10**30, "key": 1},
            "key: robot must be a whole number from 1 to 1e+06, not 1000000000000000000000000000000",
        ),
        ({"type": "touch", "robot": 1, "x": 480, "y": 0}, "touch: x must be a whole number from 0 to 479, not 480"),
        ({"type": "touch", "robot": 1, "x": 1}, "touch: field 'y' is missing"),
        ({"type": "touch", "robot": 1}, "touch: fields 'x' and 'y' are missing"),
        ({"type": "speed", "value": 1e-300}, "speed: value must be a number from 0.01 to 1000 or 'max', not 1e-300"),
        ({"type": "speed", "value": 1e308}, "speed: value must be a number from 0.01 to 1000 or 'max', not 1e+308"),
        ({"type": "pause", "why": 1}, "pause: unknown field 'why' (fields: type)"),
        (
            {"type": "digital", "robot": 1, "line": 17, "level": 1},
            "digital: line must be a whole number from 1 to 16, not 17",
        ),
        (
            {"type": "serial", "robot": 1, "interface": 1, "text": "\u20ac"},
            "serial: text must be bytes as characters U+0000..U+00FF",
        ),
        ({"type": "series", "ids": ["a"] * 33}, "series: ids must have at most 32 items"),
        ({"type": "place", "x": 1, "y": 1, "phi": 0}, "give either 'robot' or 'object' (an id), not both"),
        ({"type": "seek", "time": "soon"}, "seek: time must be a number, not 'soon'"),
    ],
)
def test_a_wrong_command_gets_one_sentence_naming_the_field(command, problem):
    assert command_problem(command) in (problem, f"place: {problem}")


def _smallest(schema: dict):
    """The smallest value a (resolved) field schema allows."""
    if "$ref" in schema:
        return _smallest(SCHEMA["$defs"][schema["$ref"].rsplit("/", 1)[1]])
    if "const" in schema:
        return schema["const"]
    if "enum" in schema:
        return schema["enum"][0]
    if "oneOf" in schema:
        return _smallest(schema["oneOf"][0])
    kind = schema["type"]
    return {
        "integer": schema.get("minimum", 1),
        "number": max(schema.get("minimum", 0.5), 0.5),
        "string": "1",
        "array": [],
        "boolean": False,
    }[kind]


def test_every_command_of_the_schema_is_carried_out():
    """A valid instance of each command (its smallest values, robot 1) gets no error: none is left
    without a handler."""
    with viewer_simulation(arena(robots=((500, 500, 0),))) as (sim, port, server):
        commands = []
        for kind, validator in command_validators().items():
            definition = validator.schema["$defs"][validator.schema["$ref"].rsplit("/", 1)[1]]
            command = {name: _smallest(definition["properties"][name]) for name in definition["required"]}
            if kind == "place":
                command["robot"] = 1
            assert command_problem(command) is None, command
            commands.append(command)

        async def send_all():
            async with aiohttp.ClientSession() as session:
                async with session.ws_connect(f"ws://127.0.0.1:{server.port}/ws", max_msg_size=0) as ws:
                    for command in commands + [{"type": "speed", "value": 1}, {"type": "paths"}]:
                        await ws.send_str(json.dumps(command))
                    errors, paths = [], 0  # timeline commands are answered in order: the last `paths` ends them
                    while paths < 2:
                        message = json.loads((await ws.receive(timeout=10)).data)
                        paths += message["type"] == "paths"
                        if message["type"] == "error":
                            errors.append(message["message"])
                    await ws.send_str(json.dumps({"type": "sentinel"}))
                    while "sentinel" not in (message := json.loads((await ws.receive(timeout=10)).data)).get(
                        "message", ""
                    ):
                        if message["type"] == "error":
                            errors.append(message["message"])
                    return errors

        assert run_async(send_all()) == []
        assert {command["type"] for command in commands} == set(command_validators())


def test_the_schema_ranges_are_the_robots_own():
    """The ranges the schema checks are the components' limits, not a second copy that could drift."""
    from eyesim.robot.components.analog_io import CHANNELS, MAX_VALUE
    from eyesim.robot.components.digital_io import LINES
    from eyesim.robot.components.keys import KEYS
    from eyesim.robot.components.lcd import HEIGHT, WIDTH
    from eyesim.robot.components.serial_ports import INTERFACES

    defs = SCHEMA["$defs"]

    def span(command: str, field: str) -> tuple:
        schema = defs[command]["properties"][field]
        return schema["minimum"], schema["maximum"]

    assert defs["KeyCommand"]["properties"]["key"]["enum"] == list(KEYS)
    assert span("TouchCommand", "x") == (0, WIDTH - 1) and span("TouchCommand", "y") == (0, HEIGHT - 1)
    assert span("DigitalCommand", "line") == (1, LINES)
    assert span("AnalogCommand", "channel") == (1, CHANNELS) and span("AnalogCommand", "value") == (0, MAX_VALUE)
    assert span("SerialCommand", "interface") == (INTERFACES.start, INTERFACES.stop - 1)
    assert defs["SerialCommand"]["properties"]["text"]["maxLength"] == 50_000  # the panel's PANEL_CHARACTERS
