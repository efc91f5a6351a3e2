"""The built-in Mako submarine in the bundled pool (`eyesim run mako_pool`), driven by C programs
numbered as the EyeSim submarine examples are: thrusters LEFT 1, FRONT 2, RIGHT 3, BACK 4; PSDs
FRONT 1, FRONT_LEFT 2, FRONT_RIGHT 3, BACK_LEFT 4, BACK_RIGHT 5, DOWN 6."""

import math
from pathlib import Path

import pytest
from support.programs import build, run_headless
from support.rooms import Run
from support.water import under_water_run

from eyesim.scene import load_robot_type

# Mako.robi and mako_pool: 35 kg, 37 litres, a 460 mm hull; 40 N thrusters; the pool is 2 m deep.
MASS, LITRES, HULL = 35.0, 37.0, 460.0
SURFACE = 2000.0
AFLOAT = SURFACE - HULL * MASS / LITRES  # the hull's bottom when it floats: 1565 mm
START = SURFACE - 300 - HULL  # its `depth 300`: the top 300 mm under the surface, the bottom at 1240 mm
UNDER_WATER = MASS / LITRES  # the part of the hull under water afloat; drag acts on that part
THRUST, DRAG_X, DRAG_TURN, THRUSTER_ARM = 40.0, 80.0, 20.0, 0.25  # N, N/(m/s), N.m/(rad/s), m


def run_in_pool(tmp_path: Path, program: Path) -> Run:
    run = Run(run_headless("mako_pool", "--program", f"1={program}", cwd=tmp_path))
    assert run.returncode == 0, run.stdout + run.stderr
    assert "warning" not in run.stderr
    return run


def test_mako_dives_holds_its_height_by_the_down_psd_and_rises_again(tmp_path, programs):
    run = run_in_pool(tmp_path, programs("mako_dive"))
    [[_, start, start_psd]] = run.values(1, "start")
    assert start == pytest.approx(START, abs=2) and start_psd == start  # starts under water; DOWN sees the floor
    [[_, dived, dived_psd]] = run.values(1, "dived")
    assert dived_psd <= 1100 and dived == pytest.approx(dived_psd, abs=2)
    holding = run.values(1, "hold")
    assert len(holding) == 10
    for _, height, psd in holding[1:]:  # after the first second: within a few mm of 1 m
        assert abs(psd - 1000) <= 10 and abs(height - psd) <= 2
    [[_, rising, _]] = run.values(1, "rising")
    assert 1000 + 100 < rising < AFLOAT - 50  # thrusters off: its buoyancy lifts it, not at once
    [[_, surfaced, surfaced_psd]] = run.values(1, "surfaced")
    assert surfaced == pytest.approx(AFLOAT, abs=3) and surfaced_psd == pytest.approx(surfaced, abs=2)


def test_mako_starts_under_water_and_rises_on_its_vertical_thrusters(tmp_path, programs):
    run = run_in_pool(tmp_path, programs("mako_rise"))
    [[_, start, start_psd]] = run.values(1, "start")
    assert start == pytest.approx(START, abs=2) and start_psd == start
    [[_, rose, _]] = run.values(1, "rose")
    # 2 x 24 N up and its 20 N of lift against 130 N per m/s: about 0.5 m/s, less the speeding up
    # (its lift alone would raise it about 0.1 m in that second)
    assert start + 250 < rose < SURFACE


def test_mako_moves_ahead_on_left_and_right_and_turns_on_one(tmp_path, programs):
    run = run_in_pool(tmp_path, programs("mako_thrust"))
    [[x0, y0, z0, phi0]] = run.values(1, "start")
    [[x1, y1, z1, phi1]] = run.values(1, "ahead")
    # Both at 50 % for 5 s: 40 N against the drag of the part under water gives the cruising speed;
    # speeding up and coasting to rest cancel out, so it goes that speed x 5 s.
    speed = 2 * 0.5 * THRUST / (DRAG_X * UNDER_WATER)
    assert x1 - x0 == pytest.approx(speed * 5 * 1000, rel=0.05)
    assert abs(y1 - y0) <= 10 and abs(phi1 - phi0) <= 1 and abs(z1 - z0) <= 5  # straight, at the surface
    [[x2, y2, z2, phi2]] = run.values(1, "turned")
    # LEFT alone, 0.25 m off the centre line, turns it clockwise (to the right) while it moves on.
    turn = math.degrees(0.5 * THRUST * THRUSTER_ARM / (DRAG_TURN * UNDER_WATER) * 5)
    assert phi2 - phi1 == pytest.approx(-turn, abs=8)
    assert x2 > x1 + 300 and y2 < y1 - 300


def test_mako_psds_see_the_pool_walls_and_floor(tmp_path):
    run = run_in_pool(tmp_path, build("psd_all", tmp_path))
    [[front, front_left, front_right, back_left, back_right, down]] = run.values(1, "psd")
    # At (2000, 3000) facing east in the 10 x 6 m pool (walls 30 mm thick on its edges): the bow
    # sensor is 670 mm ahead, the side ones 320 mm out, DOWN under the hull's bottom.
    assert front == pytest.approx(10000 - 15 - 2670, abs=2)
    for side in (front_left, front_right, back_left, back_right):
        assert side == pytest.approx(3000 - 15 - 320, abs=2)
    assert down == pytest.approx(START, abs=2)


def test_mako_ahead_and_astern_under_water_stays_level_and_at_its_depth():
    # Its centre of mass sits 30 mm below the thrusters, which are level with the hull's middle:
    # the water's drag acts there, so steady thrust does not pitch it. (With the drag at the centre
    # of mass it pitched nose down and lost depth.) FRONT and BACK hold its 2 kg of lift down.
    heights, pitches = under_water_run(load_robot_type("Mako"), ahead=(1, 3), trim={2: -24.5, 4: -24.5})
    for phase in (heights[:100], heights[140:]):  # 10 s ahead, 10 s astern: within a few cm each
        assert max(phase) - min(phase) <= 40, (min(phase), max(phase))
    assert max(abs(p) for p in pitches) <= 2
