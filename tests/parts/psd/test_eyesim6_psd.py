"""EyeSim 6 programs number PSDs 1 left, 2 front, 3 right: the scene setting EYESIM6PSD (or
`eyesim run --eyesim6-psd`) numbers a robot's sensors that way, so such programs run unmodified."""

import math

import pytest
from support.programs import build, run_headless
from support.rooms import Run, square_room, write_scene

from eyesim.parts.psd.component import eyesim6_numbering
from eyesim.scene import load_robot_type

INNER = 5  # mm: the room's walls are 10 mm thick, centred on its edges


def beam(x, y, phi, forward, left, heading):
    """(origin, direction) of an S4 sensor at (forward, left) on a robot at (x, y, phi)."""
    p = math.radians(phi)
    ox = x + forward * math.cos(p) - left * math.sin(p)
    oy = y + forward * math.sin(p) + left * math.cos(p)
    return (ox, oy), math.radians(phi + heading)


def test_an_eyesim6_program_follows_the_wall_on_its_left(drive):
    # An S4 near the north wall of a 2 m room, turned 3 degrees towards it.
    run = drive(["S4 400 1700 3"], {1: "eyesim6_wall_follow"}, size=2000, extra=["settings EYESIM6PSD"])
    [[left, front, right]] = run.values(1, "start")
    (lx, ly), ld = beam(400, 1700, 3, 0, 75, 90)
    (fx, fy), fd = beam(400, 1700, 3, 90, 0, 0)
    (rx, ry), rd = beam(400, 1700, 3, 0, -75, -90)
    assert left == pytest.approx((2000 - INNER - ly) / math.sin(ld), abs=2)  # PSD 1: the north wall
    assert front == pytest.approx((2000 - INNER - fx) / math.cos(fd), abs=2)  # PSD 2: the east wall
    assert right == pytest.approx((ry - INNER) / -math.sin(rd), abs=2)  # PSD 3: the south wall
    [[x, y, phi]] = run.values(1, "end")
    # It drove along the wall, straightened out and kept its distance, up to the east wall.
    assert x == pytest.approx(2000 - INNER - 90 - 230, abs=30) and abs(y - 1700) <= 30 and abs(phi) <= 3
    [[left, front, right]] = run.values(1, "stopped")
    assert abs(left - 220) <= 20 and front <= 250


def test_the_command_line_option_numbers_the_sensors_the_same_way(tmp_path):
    scene = write_scene(tmp_path, square_room(2000), ["S4 600 800 0"])
    program = build("psd_all", tmp_path)
    run = Run(run_headless(str(scene), "--eyesim6-psd", "--program", f"1={program}", cwd=tmp_path))
    assert run.returncode == 0, run.stderr
    [[one, two, three, four, *_]] = run.values(1, "psd")
    left, front, right, back = 2000 - INNER - 800 - 75, 2000 - INNER - 600 - 90, 800 - INNER - 75, 600 - INNER - 90
    assert (one, two, three, four) == pytest.approx((left, front, right, back), abs=2)


def test_only_the_robios7_front_and_left_trade_numbers():
    s4 = load_robot_type("S4")
    assert [(p.id, p.name) for p in eyesim6_numbering(s4.psds)] == [
        (2, "PSD_FRONT"),
        (1, "PSD_LEFT"),
        (3, "PSD_RIGHT"),
        (4, "PSD_BACK"),
    ]
    mako = load_robot_type("Mako")  # FRONT 1 but FRONT_LEFT 2: its own numbering, kept
    assert eyesim6_numbering(mako.psds) == mako.psds
