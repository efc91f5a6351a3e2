"""eyesim.Simulation: scenes with programs run from Python, and everything checks read back."""

from __future__ import annotations

import math
import signal
from pathlib import Path

import pytest
from support.scenes import arena

import eyesim
from eyesim.testing import SimulationError
from eyesim.testing.contacts import Thing
from eyesim.paths import EXAMPLES_DIR

PROGRAMS = Path(__file__).resolve().parent / "programs"
EXAMPLES = EXAMPLES_DIR


def drive_ahead(robot):
    """A Python callable program: 300 mm/s straight ahead for 8 s, then 1 s back."""
    robot.LCDPrintf("driving\n")
    robot.VWSetSpeed(300, 0)
    robot.OSWait(8000)
    robot.VWSetSpeed(-300, 0)
    robot.OSWait(1000)
    return robot.PSDGet(1)


def test_the_public_class_is_the_api_and_the_engine_keeps_its_name():
    from eyesim.core.engine import Simulation as Engine

    assert eyesim.Simulation is eyesim.testing.Simulation
    assert eyesim.Simulation is not Engine


def test_a_c_program_follows_the_wall_and_the_run_reads_back_pose_path_odometry_and_lcd(eyesim_sim, eyesim_cc):
    sim = eyesim_sim(EXAMPLES / "scenes" / "wall_follow.sim")
    sim.program(1, eyesim_cc(EXAMPLES / "programs" / "wall_follow.c"))
    end = sim.run(until=5)
    assert end.reason == "time" and end.time == 5.0
    robot = sim.robot(1)
    assert len(robot.path) == 501 and robot.path[0].t == 0 and robot.path[-1].t == 5.0
    assert (robot.path[0].x, robot.path[0].y) == pytest.approx((1000, 1750), abs=1)
    assert robot.pose.x > 1500  # it drove east along the north wall
    start = robot.path[0]
    travelled = (robot.pose.x - start.x, robot.pose.y - start.y)
    assert (robot.odometry.x, robot.odometry.y) == pytest.approx(travelled, abs=30)  # wheels agree with truth
    assert robot.lcd_text()[0] == "Wall following: left wall at 200 mm"
    assert robot.lcd_text_at(2, 0, 5) == "front"
    assert robot.menu == ["", "", "", "END"]
    assert robot.exit_code is None  # still running
    assert sim.contacts == []


def test_a_python_callable_drives_into_a_wall_and_the_contact_is_counted_and_timed(eyesim_sim):
    sim = eyesim_sim(arena(robots=((500, 1000, 0),)))
    sim.program(1, drive_ahead)
    end = sim.run(until=20)
    # 8 s + 1 s of waits, two calls of 4 ms call time (VWSetSpeed) and a local LCDPrintf (10 us)
    assert end.reason == "programs" and end.time == pytest.approx(9.008, abs=0.003)
    robot = sim.robot(1)
    assert robot.exit_code == 0 and robot.program.value > 0
    assert robot.lcd_text() == ["driving"]
    [contact] = robot.contacts("wall")
    assert contact.other(Thing("robot", 1)) == Thing("wall", 2)  # the east wall, second in the world
    assert 4 < contact.start < 6 and contact.end is not None and contact.end > contact.start
    assert robot.contacts("robot") == [] and robot.contacts("object") == []


def test_argv_stdin_environment_keys_files_and_exit_codes(eyesim_sim, eyesim_cc, tmp_path):
    sim = eyesim_sim(arena())
    sim.program(1, eyesim_cc(PROGRAMS / "io_echo.c"), "7", stdin="forty two\n", cwd=tmp_path, env={"COLOUR": "green"})
    sim.key(1, "KEY1", at=1.5)
    end = sim.run(until=10)
    robot = sim.robot(1)
    assert end.reason == "programs"
    assert robot.lcd_text_at(1, 2) == "args 2 first 7"
    assert robot.lcd_text_at(3) == "stdin forty two colour green"
    assert robot.lcd_text_at(4) == "key at 1502 ms"  # pressed at the 1.5 s step, seen after it
    assert robot.stdout == "read 'forty two'\n"
    assert robot.exit_code == 7
    assert robot.workdir == tmp_path and robot.read_file("result.txt") == b"answer forty two\n"


def test_a_condition_ends_the_run_at_the_step_it_first_holds(eyesim_sim):
    sim = eyesim_sim(arena(robots=((500, 1000, 0),)))
    sim.program(1, drive_ahead)
    end = sim.run(until=20, stop_when=lambda s: s.robot(1).pose.x > 1000)
    assert end.reason == "condition"
    assert 1000 < sim.robot(1).pose.x < 1002
    assert sim.robot(1).path[-1].x <= 1000  # the step before did not hold


def test_per_step_callbacks_see_every_step_and_their_failures_end_the_run(eyesim_sim):
    sim = eyesim_sim(arena())
    times = []
    sim.every_step(lambda s: times.append(s.time))
    sim.run(until=0.1)
    assert times == pytest.approx([0.002 * n for n in range(1, 51)])

    def check(s):
        assert s.time < 0.2, f"too late: {s.time}"

    sim.every_step(check)
    with pytest.raises(AssertionError, match="too late: 0.2"):
        sim.run(until=1)


def test_scripted_serial_and_analog_input_reach_a_python_program(eyesim_sim):
    def echo(robot):
        robot.SERInit(1, 115200, 0)
        robot.OSWait(1000)
        data = robot.SERReceive(1, 5)
        robot.SERSend(1, b"got " + data)
        return robot.ANALOGRead(2)

    sim = eyesim_sim(arena())
    sim.program(1, echo)
    sim.serial(1, 1, "hello", at=0.5)
    sim.analog(1, 2, 700, at=0.5)
    sim.run(until=5)
    assert sim.robot(1).program.error is None, sim.robot(1).stderr
    assert sim.robot(1).program.value == 700
    assert sim.robot(1).serial_output(1) == b"got hello"


def test_radio_messages_between_two_robots_are_logged(eyesim_sim):
    def sender(robot):
        robot.RADIOInit()
        robot.OSWait(100)
        robot.RADIOSend(2, b"ping")

    def receiver(robot):
        robot.RADIOInit()
        return robot.RADIOReceive()

    sim = eyesim_sim(arena(robots=((500, 500, 0), (1500, 500, 0))))
    sim.program(1, sender)
    sim.program(2, receiver)
    sim.run(until=2)
    [message] = sim.radio
    assert (message.sender, message.receiver, message.data) == (1, 2, b"ping")
    assert message.time == pytest.approx(0.104, abs=0.003)  # RADIOInit's 4 ms call time, then 100 ms
    assert sim.robot(2).program.value[1] == b"ping"


def test_a_program_that_computes_for_ever_is_stopped_by_the_wall_clock_watchdog(eyesim_sim, eyesim_cc):
    sim = eyesim_sim(arena())
    sim.program(1, eyesim_cc(PROGRAMS / "spin.c"))
    end = sim.run(until=10, wall_timeout=1.5)
    assert end.reason == "watchdog"
    assert end.time < 0.01  # deterministic time stood still while it computed
    assert sim.robot(1).lcd_text() == ["spinning"]


def test_the_cpu_limit_ends_a_program_that_computes_for_ever(eyesim_sim, eyesim_cc):
    sim = eyesim_sim(arena())
    sim.program(1, eyesim_cc(PROGRAMS / "spin.c"), cpu_seconds=1)
    end = sim.run(until=2, wall_timeout=30)
    assert end.reason in ("time", "programs")
    assert sim.robot(1).exit_code in (-signal.SIGXCPU, -signal.SIGKILL)


def test_a_crash_is_reported_with_its_signal_and_output(eyesim_sim, eyesim_cc):
    sim = eyesim_sim(arena())
    sim.program(1, eyesim_cc(PROGRAMS / "crash.c"))
    sim.run(until=5)
    robot = sim.robot(1)
    assert robot.exit_code == -signal.SIGSEGV
    assert robot.stdout == "about to crash\n"
    assert robot.pose.x > 530  # it drove before it crashed


def test_c_source_text_compiles_and_compile_errors_say_why(eyesim_sim):
    sim = eyesim_sim(arena())
    sim.c_program(1, '#include "eyebot.h"\nint main(void) { LCDPrintf("from text"); return 3; }\n')
    sim.run(until=1)
    assert sim.robot(1).lcd_text() == ["from text"] and sim.robot(1).exit_code == 3
    with pytest.raises(eyesim.CompileError, match="undeclared|implicit"):
        eyesim_sim(arena()).c_program(1, '#include "eyebot.h"\nint main(void) { return nonsense; }\n')


def test_objects_and_bad_selectors(eyesim_sim):
    sim = eyesim_sim(EXAMPLES / "scenes" / "workshop.sim")
    assert sim.object(1).pose.x == pytest.approx(1500, abs=1) and sim.object(1).name.lower() == "can"
    with pytest.raises(SimulationError, match="no robot 3 in the scene; robots: 1 \\(Reacher\\)"):
        sim.robot(3)
    with pytest.raises(SimulationError, match="no object 2"):
        sim.object(2)
    with pytest.raises(SimulationError, match="program not found"):
        sim.program(1, "/nonexistent/program")
    with pytest.raises(SimulationError, match="needs `until`"):
        sim.run()
    with pytest.raises(SimulationError, match="touch: x must be a whole number from 0 to 479, not 480"):
        sim.touch(1, 480, 10, at=1)
    with pytest.raises(SimulationError, match="'KEY5' is not KEY1..KEY4"):
        sim.key(1, "KEY5", at=1)


def test_the_same_run_twice_gives_the_same_path(eyesim_sim, eyesim_cc):
    paths = []
    for _ in range(2):
        sim = eyesim_sim(EXAMPLES / "scenes" / "wall_follow.sim")
        sim.program(1, eyesim_cc(EXAMPLES / "programs" / "wall_follow.c"))
        sim.run(until=3)
        paths.append(sim.robot(1).path)
    assert paths[0] == paths[1]
    assert math.hypot(paths[0][-1].x - paths[0][0].x, paths[0][-1].y - paths[0][0].y) > 300


def test_the_last_camera_image_and_contacts_between_robots_are_read_back(eyesim_sim):
    def look(robot):
        robot.CAMInit(0)  # QQVGA
        _, width, height, pixels = robot.CAMGet()
        return width, height, len(pixels)

    def ram(robot):
        robot.VWSetSpeed(300, 0)
        robot.OSWait(4000)

    sim = eyesim_sim(arena(robots=((500, 1000, 0), (1200, 1000, 180))))
    sim.program(1, look)
    sim.program(2, ram)
    sim.run(until=6)
    assert sim.robot(1).program.value == (160, 120, 160 * 120 * 3)
    assert sim.robot(1).camera_image().shape == (120, 160, 3)
    assert sim.robot(2).camera_image() is None
    [contact] = sim.robot(1).contacts("robot")
    assert {str(contact.first), str(contact.second)} == {"robot 1", "robot 2"} and 1 < contact.start < 4
    assert sim.robot(2).contacts("robot") == [contact] and sim.robot(1).contacts("wall") == []
