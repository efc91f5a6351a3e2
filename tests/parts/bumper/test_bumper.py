"""The bumper part (eyesim/parts/bumper/): its robot-file line and its errors, its contact strip
pressed by walls and robots as digital input 8 + id reads it, and a C program that drives into a
wall until DIGITALRead sees the press, then stops. It shows up where the other sensors do through
its component's hooks alone (robot/component.py): the viewer's rays draw a pressed strip,
recordings carry its `bumper.<id>` signal for the plots, and the robot editor checks and builds it."""

import dataclasses
import json

import jsonschema
import numpy as np
import pytest
from support.programs import run_headless
from support.rooms import Run, square_room, write_scene
from support.worlds import EXAMPLE_ROBOTS, arena_scene

from eyesim.core.clock import DETERMINISTIC, Clock
from eyesim.core.engine import Simulation
from eyesim.parts.bumper.component import Bumper
from eyesim.physics.units import mm
from eyesim.protocol.channel_schema import server_message_problems
from eyesim.record import Recorder, Recording, schemas, signals
from eyesim.record.sampling import robot_state
from eyesim.robot.components.digital_io import DigitalLines
from eyesim.robot.components.vw import VwController
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.json_format import dumps, parse_json, to_json
from eyesim.scene.robi import parse_robi, write_robi
from eyesim.viewer import messages
from eyesim.web import robot_editor

S4 = (EXAMPLE_ROBOTS / "S4.robi").read_text()
FRONT, BACK = 90, -90  # S4's front and back edges (its PSDs sit there), mm ahead of its centre
BUMPERS = f"bumper 1 {FRONT} 0 0 140\nbumper 2 {BACK} 0 180 140\n"
BUMPER_BOT = S4.replace("name S4", "name BumperBot") + BUMPERS


def read(text: str):
    diagnostics = Diagnostics()
    robot = parse_robi(text, "bot.robi", diagnostics)
    return robot, [d.message for d in diagnostics.items if d.kind == "error"]


def test_the_line_reads_writes_and_round_trips_through_json():
    robot, errors = read(BUMPER_BOT)
    assert not errors
    assert [(b.id, b.x, b.y, b.angle, b.width, b.line) for b in robot.bumpers] == [
        (1, 90.0, 0.0, 0.0, 140.0, 9),
        (2, -90.0, 0.0, 180.0, 140.0, 10),
    ]
    assert "bumper 1 90 0 0 140\nbumper 2 -90 0 180 140" in write_robi(robot)
    diagnostics = Diagnostics()
    _, again = parse_json(dumps(to_json("robot", robot)), "bot.json", diagnostics)
    assert not diagnostics.has_errors and again.bumpers == robot.bumpers


@pytest.mark.parametrize(
    "line, message",
    [
        ("bumper 1 90 0 0", "bumper: expected 5 arguments"),
        ("bumper 0 90 0 0 140", "bumper: expected bumper id, 1..8 (a whole number >= 1), found '0'"),
        ("bumper 9 90 0 0 140", "bumper: expected bumper id 1..8 (digital lines 9..16), found 9"),
        ("bumper 1 90 zero 0 140", "found 'zero'"),
        ("bumper 1 90 0 0 0", "bumper: expected width > 0, found '0'"),
        ("bumper 1 90 0 0 140\nbumper 1 -90 0 180 140", "bumper id 1 is already used: expected a different id"),
    ],
)
def test_bad_lines_are_reported(line, message):
    _, errors = read(S4 + line + "\n")
    assert any(message in error for error in errors), errors


def levels(sim, robot: int = 0) -> tuple[int, int]:
    lines = sim.robots[robot].component(DigitalLines)
    return lines.read(9), lines.read(10)


def test_a_wall_or_a_robot_presses_the_strip_that_touches_it():
    bot, _ = read(BUMPER_BOT)
    wall_x = 3000 - 5  # the arena's east wall: inner face (10 mm thick walls centred on the edge)
    sim = Simulation(
        arena_scene(
            [
                (bot, (1500, 1500, 0)),
                (bot, (wall_x - FRONT + 2, 1000, 0)),
                (bot, (1500, 2000, 0)),
                (bot, (1500 - FRONT - FRONT + 4, 2000, 0)),
            ],
            size=3000,
        )
    )
    for _ in range(3):
        sim.step()
    assert levels(sim, 0) == (1, 1)  # free: both read 1 (a switch to ground on a pulled-up line)
    assert levels(sim, 1) == (0, 1)  # its front strip against the wall
    assert levels(sim, 2) == (1, 0)  # robots 3 and 4 stand back to front: 3's back strip ...
    assert levels(sim, 3) == (0, 1)  # ... and 4's front one touch
    assert [b.id for b in sim.robots[0].components_of(Bumper)] == [1, 2]


def test_a_bumper_line_is_an_input_that_only_the_bumper_drives():
    bot, _ = read(BUMPER_BOT)
    sim = Simulation(arena_scene([(bot, (1500, 1500, 0))], size=3000))
    lines = sim.robots[0].component(DigitalLines)
    with pytest.raises(ValueError, match="digital line 9 is wired to bumper 1; it cannot be driven"):
        lines.drive(9, 0)
    with pytest.raises(ValueError, match="digital line 10 is wired to bumper 2: it can only be an input"):
        lines.setup(10, "o")
    lines.setup(9, "J")  # as an input with a pull-down it still reads the switch
    assert lines.read(9) == 1 and lines.read_all() >> 8 & 0b11 == 0b11


def test_a_program_drives_until_its_bumper_is_pressed_and_stops(tmp_path, programs):
    (tmp_path / "bumperbot.robi").write_text(BUMPER_BOT)
    scene = write_scene(tmp_path, square_room(2000), ["BumperBot 1000 1000 0"], extra=["robi bumperbot.robi"])
    program = programs("bumper_stop")
    run = Run(run_headless(str(scene), "--program", f"1={program}", cwd=tmp_path, timeout=120))
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.values(1, "released") == [[1, 1]]
    ((x, y, phi),) = run.values(1, "pressed")
    wall = 2000 - 5
    assert wall - FRONT - 10 <= x <= wall - FRONT + 5, x  # the strip (5 mm deep beyond x=90) at the wall
    assert abs(y - 1000) <= 10 and abs(phi) <= 3
    ((x2, y2, _, _, back),) = run.values(1, "stopped")
    assert abs(x2 - x) <= 10 and x2 <= wall - FRONT + 5 and back == 1  # it stopped there, not through the wall


WALL = 3000 - 5  # the arena's east wall, inner face (mm)


def pressed_and_free() -> Simulation:
    """Robot 1 free in the middle; robot 2 with its front strip against the east wall."""
    bot, _ = read(BUMPER_BOT)
    sim = Simulation(arena_scene([(bot, (1500, 1500, 0)), (bot, (WALL - FRONT + 2, 1000, 0))], size=3000))
    for _ in range(3):
        sim.step()
    return sim


def test_the_viewer_draws_a_cross_over_a_pressed_strip_only():
    sim = pressed_and_free()
    bumpers = [ray for ray in messages.sensor_rays(sim.robots) if ray["kind"] == "bumper"]
    assert [(ray["robot"], ray["id"]) for ray in bumpers] == [(2, 1)]  # not robot 1's, not robot 2's back one
    ray = bumpers[0]
    assert ray["color"] == [255, 143, 0] and len(ray["ends"]) == 6 * 3
    x, y = sim.robots[1].pose()[:2]
    assert ray["origin"][0] - x == pytest.approx(mm(FRONT + 5), abs=1e-3)  # the outer face, 5 mm beyond x=90
    ends = np.array(ray["ends"]).reshape(6, 3)
    face, arrow = ends[:4], ends[4:]
    assert np.allclose(face[:, 0], ray["origin"][0]) and np.ptp(face[:, 1]) == pytest.approx(0.14, abs=1e-3)
    assert ray["origin"][2] == pytest.approx(mm(sim.robots[1].type.height + 2), abs=1e-3)  # over the top
    assert np.all(arrow[:, 0] < ray["origin"][0] - 0.03)  # the arrowhead on the top, pointing out
    # PSD beams come first, as before, and the snapshot with them is a valid viewer message
    assert [r["kind"] for r in messages.sensor_rays(sim.robots[1:])] == ["psd"] * 4 + ["bumper"]
    sim.scene = dataclasses.replace(sim.scene, settings=dataclasses.replace(sim.scene.settings, vis=True))
    assert server_message_problems(messages.snapshot(sim)) == []


def test_a_recording_carries_the_bumper_signal_for_the_plots(tmp_path):
    bot, _ = read(BUMPER_BOT)
    sim = Simulation(arena_scene([(bot, (WALL - FRONT - 100, 1500, 0))], size=3000), Clock(DETERMINISTIC))
    with Recorder(sim, tmp_path / "run.mcap"):
        sim.robots[0].component(VwController).set_speed(0.2, 0.0)  # 100 mm to go: pressed after 0.5 s
        sim.run(until=1.0)
    with Recording(tmp_path / "run.mcap") as recording:
        found = {s["id"]: s for s in signals.catalogue(recording)}
        assert found["robot/1/bumper.1"]["unit"] == "pressed" and "robot/1/bumper.2" in found
        times, values = signals.series(recording, "robot/1/bumper.1")
        assert set(values) == {0.0, 1.0} and values[0] == 0.0 and values[-1] == 1.0
        first = times[values.index(1.0)]
        assert 0.4 < first < 0.6, first
        assert set(signals.series(recording, "robot/1/bumper.2")[1]) == {0.0}
        assert signals.series(recording, "robot/1/bumper.3") is None  # no such part: an unknown signal
        state = recording.states[1][-1][1]
        jsonschema.validate(state, schemas.SCHEMAS["eyesim.RobotState"])
        assert state["signals"] == {"bumper.1": [1, "pressed"], "bumper.2": [0, "pressed"]}


def test_a_robot_without_parts_that_give_signals_records_its_state_as_before():
    sim = Simulation(arena_scene([("S4", (1500, 1500, 0))]))
    assert set(robot_state(sim.robots[0])) == {"robot", "odometry", "speed", "encoders", "battery"}


def test_the_robot_editor_checks_and_builds_a_robot_with_bumpers():
    bot, _ = read(BUMPER_BOT)
    document = robot_editor.full_json(bot)
    assert document["bumpers"][0] == {"id": 1, "x": 90.0, "y": 0.0, "angle": 0.0, "width": 140.0}
    document["bumpers"][1]["id"] = 9
    _, problems = robot_editor.check_document(json.loads(json.dumps(document)))
    assert [p["pointer"] for p in problems if p["kind"] == "error"] == ["/bumpers/1"]
    sim = robot_editor.build(bot, 1000)
    drawn = robot_editor.sensors(sim)
    assert len(drawn["psds"]) == 4 and drawn["lidar"] is None and drawn["camera"] is not None
