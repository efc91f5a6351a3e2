"""The examples a student gets run as their comments say and do their jobs.

Every command written at the top of an example (a comment line `#   eyesim run ...` in a scene or
Python file, ` *   eyesim run ...` in a C file) is run exactly as written from the examples folder,
headless and bounded by `--until` (and the soft keys the program waits for), so the documented
commands cannot rot; the tests per example then check what each run did: where the robots went
(--record CSV), what their LCDs show (--save-lcd PNGs, compared with text drawn by the simulator's
own LCD), what the programs printed. C sources are compiled by `eyesim run` itself, into a cache of
this test session. Each command runs once per session; the commands and the checks share the runs.

The runs happen in a copy of the examples folder, as a student has it, so that files the programs
write (lidar_map's map.pgm) stay out of the checkout."""

from __future__ import annotations

import math
import os
import re
import shlex
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from support.programs import eyesim_command, read_trajectory, run_headless

from eyesim.robot.components.lcd import Lcd
from eyesim.paths import EXAMPLES_DIR

EXAMPLES = EXAMPLES_DIR  # the examples folder: the one place that says where

COMMAND_LINE = re.compile(r"^\s*(?:#|\*)\s+(eyesim run\b.*?)\s*$")
EXAMPLE_FILES = (".c", ".cpp", ".py", ".sim")


@dataclass(frozen=True)
class Bounds:
    """How long a run of an example lasts (simulation seconds) and the input its programs wait for."""

    until: float
    inputs: tuple[str, ...] = ()


# Per scene (or, on the default arena, per program): each run is bounded by --until, a few seconds
# of simulation time after its programs are done; programs that run until KEY4 get it.
BOUNDS = {
    "programs/demo": Bounds(6, ("--key", "1:KEY4@4")),
    "programs/menu_demo": Bounds(
        8, ("--key", "1:KEY1@1", "--key", "1:KEY2@3", "--key", "1:KEY3@5", "--key", "1:KEY4@6")
    ),
    "scenes/wall_follow.sim": Bounds(12, ("--key", "1:KEY4@10")),
    "scenes/lidar_map.sim": Bounds(10, ("--key", "1:KEY4@8")),
    "scenes/colour_track.sim": Bounds(12),  # arrives at about 8 s
    "scenes/drive_types.sim": Bounds(20),  # done at about 17 s
    "scenes/pool.sim": Bounds(28),  # surfaced at about 25 s
    "scenes/workshop.sim": Bounds(22),  # done at about 19 s
    "scenes/maze.sim": Bounds(38),  # at the finish at about 35 s
    "scenes/radio.sim": Bounds(10),  # done at about 8 s
}


def documented_commands() -> dict[str, list[Path]]:
    """Every `eyesim run` command in the examples' comments -> the files that give it."""
    commands: dict[str, list[Path]] = {}
    for path in sorted(EXAMPLES.rglob("*")):
        if path.suffix in EXAMPLE_FILES:
            for line in path.read_text().splitlines():
                match = COMMAND_LINE.match(line)
                if match:
                    commands.setdefault(match.group(1), []).append(path.relative_to(EXAMPLES))
    return commands


def example_of(command: str) -> str:
    """The BOUNDS key of a command: its scene, else (the default arena) robot 1's program."""
    args = shlex.split(command)[2:]
    if args and not args[0].startswith("-"):
        return args[0]
    program = next(value for option, value in zip(args, args[1:]) if option == "--program" and value.startswith("1="))
    return str(Path(program[2:]).with_suffix(""))


def commands_for(example: str) -> list[str]:
    return [command for command in documented_commands() if example_of(command) == example]


@dataclass
class ExampleRun:
    command: str
    stdout: str
    stderr: str
    out: Path  # the run's CSV, LCD images and the files its programs wrote

    def lines(self, robot: int) -> list[str]:
        """What robot's program printed, without the simulator's prefix."""
        prefix = f"[robot {robot}] "
        return [line[len(prefix) :] for line in self.stdout.splitlines() if line.startswith(prefix)]

    def values(self, robot: int, tag: str) -> list[int]:
        """The numbers of the one line `<tag> n n ...` robot printed."""
        [line] = [line for line in self.lines(robot) if line.split()[:1] == [tag]]
        return [int(word) for word in line.split()[1:] if re.fullmatch(r"-?\d+", word)]

    def path(self, robot: int) -> list[dict]:
        """The robot's true poses every 10 ms (metres; the CSV's columns)."""
        return read_trajectory(self.out / "path.csv")[robot]

    def lcd(self, robot: int) -> np.ndarray:
        return np.asarray(Image.open(self.out / "lcd" / f"robot{robot}-lcd.png").convert("RGB"))

    def lcd_shows(
        self, robot: int, row: int, text: str, column: int = 0, colours: tuple[int, int] | None = None
    ) -> bool:
        """Whether robot's final LCD shows `text` at (row, column) of the default font's grid, in
        white on black or in `colours` (foreground, background): pixel for pixel as the
        simulator's LCD draws it."""
        expected = Lcd()
        if colours:
            expected.set_color(*colours)
        expected.set_position(row, column)
        expected.print(text)
        width, height = expected.cell
        box = (slice(row * height, (row + 1) * height), slice(column * width, (column + len(text)) * width))
        return np.array_equal(self.lcd(robot)[box], expected.screen()[box])

    def written(self, name: str) -> Path:
        return self.out / "written" / name


@pytest.fixture(scope="session")
def run_example(tmp_path_factory):
    """run_example(command) -> ExampleRun: the documented command, from the copy of the examples
    that `eyesim examples` makes, as a student does, headless with its BOUNDS, recording the robots'
    paths and LCDs; once per session."""
    folder = tmp_path_factory.mktemp("student") / "examples"
    copied = subprocess.run(eyesim_command("examples", str(folder)), capture_output=True, text=True)
    assert copied.returncode == 0, copied.stderr
    assert "Try: cd" in copied.stdout
    env = {**os.environ, "EYESIM_CACHE_DIR": str(tmp_path_factory.mktemp("cache"))}
    runs: dict[str, ExampleRun] = {}

    def run(command: str) -> ExampleRun:
        if command in runs:
            return runs[command]
        words = shlex.split(command)
        assert words[:2] == ["eyesim", "run"] and "--headless" not in words and "--until" not in words, command
        assert example_of(command) in BOUNDS, f"{command}: add how long it runs to BOUNDS"
        bounds = BOUNDS[example_of(command)]
        out = tmp_path_factory.mktemp("run")
        before = {p for p in folder.rglob("*") if p.is_file()}
        result = run_headless(
            *words[2:],
            "--until",
            str(bounds.until),
            *bounds.inputs,
            "--record",
            str(out / "path.csv"),
            "--save-lcd",
            str(out / "lcd"),
            cwd=folder,
            env=env,
        )
        (out / "written").mkdir()
        for made in {p for p in folder.rglob("*") if p.is_file()} - before:  # keep them with this run
            shutil.move(made, out / "written" / made.name)
        said = f"{command}\n{result.stdout}{result.stderr}"
        assert result.returncode == 0, said
        assert "warning" not in result.stderr.lower() and "not found" not in result.stderr, said
        summary = [line for line in result.stdout.splitlines() if re.match(r"robot \d+ \S+: x=", line)]
        assert summary and all(
            re.search(r"program \S+: (exit code 0|still running at the end \(stopped\))$", line) for line in summary
        ), said
        runs[command] = ExampleRun(command, result.stdout, result.stderr, out)
        return runs[command]

    return run


def near(row: dict, x_mm: float, y_mm: float) -> float:
    """Distance in mm of a pose row (metres) from a point."""
    return math.hypot(row["x"] * 1000 - x_mm, row["y"] * 1000 - y_mm)


def heading(row: dict) -> float:
    """Heading of a pose row in degrees (robots stay upright: rotation about z only)."""
    return math.degrees(2 * math.atan2(row["qz"], row["qw"]))


# -- the documented commands --------------------------------------------------------------------
def test_every_example_documents_how_to_run_it_and_has_a_python_version():
    commands = documented_commands()
    named = " ".join(commands)
    for program in sorted((EXAMPLES / "programs").iterdir()):
        if program.suffix in (".c", ".py"):
            assert f"programs/{program.name}" in named, f"no documented command runs {program.name}"
            assert any(Path("programs") / program.name in files for files in commands.values()), (
                f"{program.name} says nowhere how to run it"
            )
        if program.suffix == ".c":
            assert program.with_suffix(".py").is_file(), f"{program.name} has no Python version"
    for scene in sorted((EXAMPLES / "scenes").glob("*.sim")):
        own = [command for command, files in commands.items() if Path("scenes") / scene.name in files]
        assert any(shlex.split(command)[2] == f"scenes/{scene.name}" for command in own), (
            f"{scene.name} says nowhere how to run it"
        )
    assert {example_of(command) for command in commands} == set(BOUNDS)  # every run has bounds, all bounds a run


@pytest.mark.parametrize("command", sorted(documented_commands()), ids=str)
def test_every_documented_command_runs_as_written(run_example, command):
    run = run_example(command)
    assert run.lines(1) or run.lcd(1).any(), f"{command}: robot 1's program did nothing visible"


# -- what each example does ---------------------------------------------------------------------
@pytest.mark.parametrize("command", commands_for("programs/demo"), ids=str)
def test_demo_explores_until_key4(run_example, command):
    run = run_example(command)
    assert run.lines(1) == ["demo: started", "demo: ended by KEY4"]
    assert run.lcd_shows(1, 0, "EyeSim demo: S4 explores the arena") and run.lcd_shows(1, 12, "bye")
    path = run.path(1)
    assert max(row["x"] for row in path) - path[0]["x"] > 0.4  # explored


@pytest.mark.parametrize("command", commands_for("programs/menu_demo"), ids=str)
def test_menu_demo_does_what_each_key_says(run_example, command):
    run = run_example(command)
    end = run.path(1)[-1]
    assert near(end, 700, 500) < 10 and abs(heading(end) - 90) < 2  # DRIVE: 200 mm, then TURN: 90 degrees
    for row, text in [(12, "DRIVE: 200 mm forward"), (13, "TURN: 90 degrees to the left"), (14, "BEEP!")]:
        assert run.lcd_shows(1, row, text), f"the log's row {row} does not show {text!r}"
    assert run.lcd_shows(1, 9, " Goodbye! ", colours=(0x000000, 0xFFFF00))
    assert "[robot 1 audio] beep" in run.stdout


@pytest.mark.parametrize("command", commands_for("scenes/wall_follow.sim"), ids=str)
def test_wall_follow_goes_round_the_corner(run_example, command):
    run = run_example(command)
    path = run.path(1)
    assert min(near(row, 2150, 1720) for row in path if row["time_s"] <= 6) < 100  # along the north wall
    assert min(near(row, 2215, 1080) for row in path if row["time_s"] <= 10) < 100  # down the east wall
    assert re.fullmatch(r"wall following done after 100\d\d ms", run.lines(1)[-1])
    assert run.lcd_shows(1, 0, "Wall following: left wall at 200 mm")


@pytest.mark.parametrize("command", commands_for("scenes/lidar_map.sim"), ids=str)
def test_lidar_map_saves_its_map(run_example, command):
    run = run_example(command)
    [scans] = run.values(1, "mapped")
    assert 60 <= scans < 150  # a scan every 50 ms and its calls' 4 ms each, for 8 s
    data = run.written("map.pgm").read_bytes()
    header = b"P5\n300 300\n255\n"
    assert data.startswith(header) and len(data) == len(header) + 300 * 300
    assert data[len(header) :].count(0) > 200  # walls seen
    assert run.lcd_shows(1, 0, "Lidar map (1 pixel = 20 mm)")
    lcd = run.lcd(1)
    assert (lcd[20:280, 100:] == 255).all(axis=2).sum() > 200  # the map drawn on the LCD
    path = run.path(1)
    assert near(path[-1], path[0]["x"] * 1000, path[0]["y"] * 1000) > 500  # it wandered


@pytest.mark.parametrize("command", commands_for("scenes/colour_track.sim"), ids=str)
def test_colour_track_drives_up_to_the_red_pillar(run_example, command):
    run = run_example(command)
    [line] = run.lines(1)
    [pixels] = re.fullmatch(r"arrived: the target fills (\d+) of 19200 pixels", line).groups()
    assert int(pixels) > 19200 / 4
    path = run.path(1)
    assert near(path[-1], 1900, 1450) < near(path[0], 1900, 1450) - 600
    camera = run.lcd(1)[:120, :160].astype(int)  # the last camera image on the LCD
    red = (camera[..., 0] > 120) & (camera[..., 0] > 2 * camera[..., 1]) & (camera[..., 0] > 2 * camera[..., 2])
    assert red.mean() > 0.2


@pytest.mark.parametrize("command", commands_for("scenes/drive_types.sim"), ids=str)
def test_drive_types_car_slaloms_mecanum_squares_trolley_pushes(run_example, command):
    run = run_example(command)
    car = run.path(1)
    assert car[-1]["x"] - car[0]["x"] > 1.5  # the car went a long way east ...
    assert max(row["y"] for row in car) - min(row["y"] for row in car) > 0.1  # ... weaving
    omni = run.path(2)
    start = omni[0]
    assert near(omni[-1], start["x"] * 1000, start["y"] * 1000) < 20  # the square closed
    assert min(row["x"] for row in omni) < start["x"] - 0.55  # 600 mm back ...
    assert min(row["y"] for row in omni) < start["y"] - 0.55  # ... and 600 mm to the right
    assert max(abs(heading(row)) for row in omni) < 3  # never turning
    crate_x, crate_y = run.values(3, "crate")
    assert crate_x > 900 + 400 and abs(crate_y - 2600) < 30  # the crate, pushed east
    assert run.lcd_shows(1, 0, "Car slalom") and run.lcd_shows(2, 1, "back at the start")
    assert run.lcd_shows(3, 1, f"crate now at {crate_x} {crate_y}")


@pytest.mark.parametrize("command", commands_for("scenes/pool.sim"), ids=str)
def test_submarine_dives_holds_its_depth_and_surfaces(run_example, command):
    run = run_example(command)
    [dived], [cruised], [surfaced] = run.values(1, "dived"), run.values(1, "cruised"), run.values(1, "surfaced")
    assert abs(dived - 500) < 60 and abs(cruised - 500) < 60 and surfaced <= 0
    path = run.path(1)
    depth = {round(row["time_s"], 2): 1.5 - (row["z"] + 0.2) for row in path}  # the hull top's: rim 1.5 m, hull 0.2 m
    held = [d for t, d in depth.items() if 8 <= t <= 18]
    assert abs(depth[8.0] - depth[0.01]) > 0.3  # it went to its depth ...
    assert all(abs(d - 0.5) < 0.08 for d in held)  # ... held it while cruising and turning ...
    assert path[-1]["time_s"] > 25 and depth[round(path[-1]["time_s"], 2)] < 0.02  # ... and surfaced
    assert path[-1]["x"] - path[0]["x"] > 1.0  # it cruised ahead
    assert run.lcd_shows(1, 0, "Going to 500 mm depth")
    assert run.lcd_shows(1, 3, f"at the surface: depth {surfaced} mm")


@pytest.mark.parametrize("command", commands_for("scenes/workshop.sim"), ids=str)
def test_arm_moves_the_can(run_example, command):
    run = run_example(command)
    x, y, z = run.values(1, "can")
    assert math.hypot(x - 1790, y - 1421) < 30 and abs(z) < 5  # standing at its new place, 390 mm from its old
    assert run.lcd_shows(1, 1, f"can at {x} {y}")
    arm = run.path(1)
    assert near(arm[-1], 1500, 1500) < 1  # bolted to the floor


@pytest.mark.parametrize("command", commands_for("scenes/maze.sim"), ids=str)
def test_maze_right_hand_rule_reaches_the_finish(run_example, command):
    run = run_example(command)
    assert run.lines(1) == ["finish reached at cell 4 3 in 15 moves"]
    path = run.path(1)
    assert near(path[0], 180, 180) < 30  # from the start cell (S, bottom left) ...
    assert near(path[-1], 1620, 1260) < 60  # ... to the finish cell (F, top right), by the truth
    assert run.lcd_shows(1, 0, "Right-hand rule: finish at cell (4, 3)")
    assert run.lcd_shows(1, 16, "Finish reached in 15 moves")


RADIO_COMMANDS = ["forward 600", "left 90", "forward 400", "left 90", "forward 300", "stop"]


@pytest.mark.parametrize("command", commands_for("scenes/radio.sim"), ids=str)
def test_radio_commands_drive_the_other_robot(run_example, command):
    run = run_example(command)
    assert run.lines(2) == [f'got "{sent}" from robot 1' for sent in RADIO_COMMANDS]
    answers = run.lines(1)
    assert len(answers) == len(RADIO_COMMANDS) and answers[-1] == "robot 2 answered: stopped"
    expected = [(600, 0, 0), (600, 0, 90), (600, 400, 90), (600, 400, 180), (300, 400, 180)]  # odometry
    for sent, answer, (x, y, phi) in zip(RADIO_COMMANDS, answers, expected):
        match = re.fullmatch(rf"robot 2 answered: done {sent}, now at x (-?\d+) y (-?\d+) phi (-?\d+)", answer)
        assert match, answer
        got_x, got_y, got_phi = map(int, match.groups())
        assert abs(got_x - x) <= 5 and abs(got_y - y) <= 5 and abs((got_phi - phi + 180) % 360 - 180) <= 2, answer
    driver, commander = run.path(2), run.path(1)
    assert near(driver[-1], 1300, 1100) < 20 and abs(abs(heading(driver[-1])) - 180) < 2  # where it was told to go
    assert near(commander[-1], 500, 500) < 5  # the commander stays put
    assert run.lcd_shows(1, 13, "all 6 commands done") and run.lcd_shows(2, 7, "stopped")


def test_eyesim_examples_copies_them_and_will_not_overwrite(tmp_path):
    target = tmp_path / "ex"
    done = subprocess.run(eyesim_command("examples", str(target)), capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    copied = sorted(p.relative_to(target) for p in target.rglob("*") if p.is_file())
    shipped = sorted(
        p.relative_to(EXAMPLES) for p in EXAMPLES.rglob("*") if p.is_file() and "__pycache__" not in p.parts
    )
    assert copied == shipped and Path("scenes/wall_follow.sim") in copied
    again = subprocess.run(eyesim_command("examples", str(target)), capture_output=True, text=True)
    assert again.returncode == 2 and "already exists and is not an empty folder" in again.stderr
