"""The bumper part (eyesim/parts/bumper/): its robot-file line and its errors, its contact strip
pressed by walls and robots as digital input 8 + id reads it, and a C program that drives into a
wall until DIGITALRead sees the press, then stops."""

import pytest
from support.programs import run_headless
from support.rooms import Run, square_room, write_scene
from support.worlds import EXAMPLE_ROBOTS, arena_scene

from eyesim.core.engine import Simulation
from eyesim.parts.bumper.component import Bumper
from eyesim.robot.components.digital_io import DigitalLines
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.json_format import dumps, parse_json, to_json
from eyesim.scene.robi import parse_robi, write_robi

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
