"""A real C program, built with `eyesim cc`, drives S4 in a real `eyesim run` process."""

import json
import math
import os
import signal
import subprocess
import time
from pathlib import Path

import numpy as np
from PIL import Image
from support.programs import build, eyesim_command, read_trajectory, run_headless

from eyesim.robot.components.lcd import CELL_HEIGHT, HEIGHT, MENU_HEIGHT
from eyesim.paths import EXAMPLES_DIR


def heading(row) -> float:
    return math.degrees(2 * math.atan2(row["qz"], row["qw"]))


def test_drive_turn_print_and_key(tmp_path):
    program = build("drive_square_corner", tmp_path)
    result = run_headless(
        "--program", f"1={program}", "--key", "1:KEY1@0.5", "--record", "path.csv", "--save-lcd", "lcd", cwd=tmp_path
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert "done key=1" in result.stdout
    assert "program drive_square_corner: exit code 0" in result.stdout

    path = read_trajectory(tmp_path / "path.csv")[1]
    start, end = path[0], path[-1]
    start_heading = heading(start)
    expected_x = start["x"] + math.cos(math.radians(start_heading))
    expected_y = start["y"] + math.sin(math.radians(start_heading))
    assert math.hypot(end["x"] - expected_x, end["y"] - expected_y) < 0.010  # within 10 mm of 1000
    turned = (heading(end) - start_heading + 180) % 360 - 180
    assert abs(turned - 90) < 1.0

    lcd = np.asarray(Image.open(tmp_path / "lcd" / "robot1-lcd.png").convert("RGB"))
    text_rows = [lcd[r * CELL_HEIGHT : (r + 1) * CELL_HEIGHT] for r in range(3)]
    assert all((row > 200).all(axis=2).sum() > 20 for row in text_rows)  # three printed lines
    assert not (lcd[3 * CELL_HEIGHT : HEIGHT - MENU_HEIGHT] > 0).any()  # nothing below them
    assert (lcd[HEIGHT - MENU_HEIGHT :] > 0).any()  # the menu bar is drawn


def test_deterministic_runs_are_bit_identical(tmp_path):
    program = build("drive_square_corner", tmp_path)
    for name in ("first", "second"):
        result = run_headless(
            "--program", f"1={program}", "--key", "1:KEY1@0.3", "--record", f"{name}.csv", cwd=tmp_path
        )
        assert result.returncode == 0, result.stderr
    first, second = (tmp_path / "first.csv").read_bytes(), (tmp_path / "second.csv").read_bytes()
    assert len(first.splitlines()) > 300
    assert first == second


def test_a_failing_program_fails_the_run(tmp_path):
    program = build("drive_square_corner", tmp_path)
    result = run_headless("--program", f"1={program}", "--key", "1:KEY2@0.1", cwd=tmp_path)
    assert result.returncode == 1
    assert "exit code 9" in result.stdout


def test_a_missing_program_is_reported(tmp_path):
    result = run_headless("--program", "1=./no-such-program", cwd=tmp_path)
    assert result.returncode == 1
    assert "program not found" in result.stdout + result.stderr


def test_the_program_ends_clearly_when_the_simulator_dies(tmp_path):
    program = build("wait_forever", tmp_path)
    simulator = subprocess.Popen(
        eyesim_command("run", "--headless", "--clock", "realtime", "--port", "0"),
        stdout=subprocess.PIPE,
        text=True,
        cwd=tmp_path,
    )
    try:
        line = simulator.stdout.readline()
        while "programs connect to" not in line:
            line = simulator.stdout.readline()
            assert line, "the simulator did not start"
        port = line.rsplit(":", 1)[1].split()[0]
        client = subprocess.Popen(
            [str(program)],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            env=dict(os.environ, EYESIM_PORT=port),
        )
        assert client.stdout.readline().strip() == "ready"
        time.sleep(0.2)
        simulator.send_signal(signal.SIGKILL)
        out, err = client.communicate(timeout=20)
        assert client.returncode != 0
        assert "VWWait returned" not in out
        assert "simulator" in err.lower()
    finally:
        simulator.kill()
        simulator.wait()


def test_program_output_reaches_the_console_line_by_line(tmp_path):
    program = build("print_then_wait", tmp_path)
    simulator = subprocess.Popen(
        eyesim_command("run", "--headless", "--clock", "realtime", "--port", "0", "--program", f"1={program}"),
        stdout=subprocess.PIPE,
        text=True,
        cwd=tmp_path,
    )
    try:
        start = time.perf_counter()
        line = simulator.stdout.readline()
        while "hello before waiting" not in line:
            line = simulator.stdout.readline()
            assert line, "the program's first line never arrived"
        assert line.startswith("[robot 1] ")
        assert time.perf_counter() - start < 2.5  # long before the program's 3 s wait ends
        out, _ = simulator.communicate(timeout=30)
        assert "after waiting" in out and simulator.returncode == 0
    finally:
        simulator.kill()


def test_the_bundled_demo_explores_and_ends_on_key4(tmp_path):
    demo = EXAMPLES_DIR / "programs" / "demo.c"
    output = tmp_path / "demo"
    built = subprocess.run(
        eyesim_command("cc", "-Wall", "-Wextra", "-Werror", str(demo), "-o", str(output)),
        capture_output=True,
        text=True,
    )
    assert built.returncode == 0, built.stderr
    result = run_headless("--program", f"1={output}", "--key", "1:KEY4@6", "--record", "path.csv", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "demo: ended by KEY4" in result.stdout
    path = read_trajectory(tmp_path / "path.csv")[1]
    travelled = sum(math.hypot(b["x"] - a["x"], b["y"] - a["y"]) for a, b in zip(path, path[1:]))
    assert travelled > 0.8  # it explored: about 250 mm/s for most of 6 s


def _log(recording: Path) -> list[tuple[int, str]]:
    from mcap.reader import make_reader

    with open(recording, "rb") as file:
        return [
            (message.log_time, json.loads(message.data)["message"])
            for _, _, message in make_reader(file).iter_messages(topics=["/log"])
        ]


def test_program_output_is_stamped_when_the_program_wrote_it(tmp_path):
    """Deterministic runs: a line is taken in before the program's next call, at the simulation
    time it was written, however late the operating system lets the simulator read the pipe; the
    console and the recording repeat exactly."""
    program = build("print_as_time_goes", tmp_path)
    logs = []
    for name in ("first", "second"):
        result = run_headless("--program", f"1={program}", "--record", f"{name}.mcap", cwd=tmp_path)
        assert result.returncode == 0, result.stderr
        logs.append(_log(tmp_path / f"{name}.mcap"))
    assert logs[0] == logs[1]
    lines = [(time_ns, text) for time_ns, text in logs[0] if text.startswith("at ")]
    assert len(lines) == 40
    for time_ns, text in lines:
        written_ms = int(text.split()[1])
        assert written_ms - 2 <= time_ns / 1e6 <= written_ms + 4, (time_ns, text)  # within its step and call
    halves = [text for _, text in logs[0] if "half" in text]
    assert halves == ["first half, ", "second half"]  # broken where the program made its call
