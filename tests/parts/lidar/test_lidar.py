"""LIDARSet/LIDARGet from a real C program: a scan of a square room against its geometry, the
index convention, a narrow field, a tilted plane, bad settings, and beams past the robot itself."""

import math
from pathlib import Path

from support.rooms import square_room, write_scene
from support.scenes import arena

import eyesim
from eyesim.core.engine import Simulation
from eyesim.parts.lidar.component import MOUNT_ABOVE_TOP, LidarScanner

ROOM = 2000
INNER = (5.0, ROOM - 5.0)
S4_HEIGHT = 90  # mm (eyesim/data/robots/S4.robi): the scanner sits MOUNT_ABOVE_TOP above it


def to_wall(x: float, y: float, heading_deg: float) -> float:
    """Distance from (x, y) along a heading to the room's first inner wall face."""
    dx, dy = math.cos(math.radians(heading_deg)), math.sin(math.radians(heading_deg))
    return min(
        (face - start) / delta
        for start, delta in ((x, dx), (y, dy))
        for face in INNER
        if abs(delta) > 1e-12 and (face - start) / delta > 0
    )


def beam_heading(phi: float, index: int, points: int, field: float) -> float:
    """The documented convention: beam i is (i - points/2) * field/points degrees clockwise from ahead."""
    return phi - (index - points // 2) * field / points


def test_a_scan_matches_the_room_and_the_index_convention(tmp_path, programs, run_scene):
    x, y, phi = 650, 800, 20  # off-centre and turned, so a wrong index convention cannot match
    scene = write_scene(tmp_path, square_room(ROOM), [f"S4 {x} {y} {phi}"])
    run = run_scene(scene, {1: programs("lidar_scan")})
    assert run.returncode == 0, run.stdout + run.stderr

    rc, points, *scan = run.values(1, "default")[0]
    assert (rc, points, len(scan)) == (0, 360, 360)
    for i, measured in enumerate(scan):
        assert abs(measured - to_wall(x, y, beam_heading(phi, i, 360, 360))) <= 10, (i, measured)
    # 0 behind, 90 left, 180 ahead, 270 right: the ahead beam reaches the east wall first
    assert abs(scan[180] - to_wall(x, y, phi)) <= 10 and abs(scan[90] - to_wall(x, y, phi + 90)) <= 10
    assert abs(scan[270] - to_wall(x, y, phi - 90)) <= 10 and abs(scan[0] - to_wall(x, y, phi + 180)) <= 10

    assert run.values(1, "set")[0] == [0]
    rc, points, *narrow = run.values(1, "narrow")[0]
    assert (rc, points, len(narrow)) == (0, 8, 8)
    for i, measured in enumerate(narrow):  # 8 beams 22.5 degrees apart from 90 left to 67.5 right
        assert abs(measured - to_wall(x, y, beam_heading(phi, i, 8, 180))) <= 10, (i, measured)


def test_the_legacy_laser_scan_is_counter_clockwise_from_ahead_and_keeps_the_lidar_settings(
    tmp_path, programs, run_scene
):
    x, y, phi = 650, 800, 20
    scene = write_scene(tmp_path, square_room(ROOM), [f"S4 {x} {y} {phi}"])
    run = run_scene(scene, {1: programs("laser_scan")})
    assert run.returncode == 0, run.stdout + run.stderr

    assert run.values(1, "set")[0] == [0]
    rc, *scan = run.values(1, "laser")[0]
    assert (rc, len(scan)) == (0, 360)
    # index i at i degrees counter-clockwise from ahead: 0 ahead, 90 left, 180 behind, 270 right
    for i, wall in ((0, phi), (90, phi + 90), (180, phi + 180), (270, phi - 90)):
        assert abs(scan[i] - to_wall(x, y, wall)) <= 10, (i, scan[i])
    for i, measured in enumerate(scan):  # programs map a wall point at x + d*cos(phi + i)
        assert abs(measured - to_wall(x, y, phi + i)) <= 10, (i, measured)

    # The program's own LIDARSet(180, 0, 8) is untouched: LIDARGet still gives its 8 beams.
    assert run.values(1, "resolution")[0] == [8]
    rc, *narrow = run.values(1, "narrow")[0]
    assert (rc, len(narrow)) == (0, 8)
    for i, measured in enumerate(narrow):
        assert abs(measured - to_wall(x, y, beam_heading(phi, i, 8, 180))) <= 10, (i, measured)
    assert run.values(1, "null")[0] == [1]
    assert "eyesim: SIMLaserScan: the scan array is NULL" in run.stderr


def test_a_tilted_scan_sees_the_floor_ahead_and_the_wall_behind(tmp_path, programs, run_scene):
    scene = write_scene(tmp_path, square_room(ROOM), ["S4 1000 1000 0"])
    run = run_scene(scene, {1: programs("lidar_scan")})
    assert run.returncode == 0, run.stdout + run.stderr
    rc, points, *tilted = run.values(1, "tilted")[0]
    assert (rc, points) == (0, 360)
    height = S4_HEIGHT + MOUNT_ABOVE_TOP
    assert abs(tilted[180] - height / math.sin(math.radians(10))) <= 10  # ahead: down onto the floor
    assert abs(tilted[0] - (ROOM / 2 - 5) / math.cos(math.radians(10))) <= 10  # behind: up onto the wall
    assert abs(tilted[90] - (ROOM / 2 - 5)) <= 10  # the sides stay level

    assert run.values(1, "bad")[0] == [1, 1, 1, 1]
    assert run.values(1, "still")[0] == [360]
    assert "LIDARSet: range 0 is not a field of view of 1..360 degrees" in run.stderr
    assert "LIDARSet: 3601 points; expected 1..3600" in run.stderr


def test_beams_pass_the_robots_own_chassis_and_wheels():
    """Tilted 80 degrees, the front beams go down through S4's chassis and past its wheels to the
    floor: each measures the floor, never the robot itself."""
    sim = Simulation(arena(robots=((1000, 1000, 0),)))
    scanner = sim.robots[0].component(LidarScanner)
    scanner.configure(360, 80, 360)
    scan = scanner.scan()
    height = S4_HEIGHT + MOUNT_ABOVE_TOP
    for i in range(120, 241):  # up to 60 degrees either side of ahead
        clockwise = math.radians(i - 180)
        floor = height / (math.cos(clockwise) * math.sin(math.radians(80)))
        assert abs(scan[i] - floor) <= 2, (i, scan[i], floor)


def test_a_scan_never_overruns_the_programs_array(tmp_path, programs, run_scene):
    """A robot file with a 720-point lidar, and a program with room for LIDAR_RESOLUTION (360)."""
    s4 = (Path(eyesim.__file__).parent / "data" / "robots" / "S4.robi").read_text()
    (tmp_path / "wide.robi").write_text(s4.replace("name S4", "name Wide") + "lidar 720 0\n")
    scene = write_scene(tmp_path, square_room(ROOM), ["Wide 1000 1000 0"], extra=["robi wide.robi"])
    run = run_scene(scene, {1: programs("lidar_scan")})
    assert run.returncode == 0, run.stdout + run.stderr
    rc, points, *scan = run.values(1, "default")[0]
    assert (rc, points, len(scan)) == (1, 360, 360)  # the first 360 of 720 half-degree beams
    for i, measured in enumerate(scan):
        assert abs(measured - to_wall(1000, 1000, beam_heading(0, i, 720, 360))) <= 10, (i, measured)
    assert "LIDARGet: the robot's lidar has 720 points, LIDAR_RESOLUTION is 360" in run.stderr
    assert run.values(1, "narrow")[0][:2] == [0, 8]  # after LIDARSet all is well


def test_a_scan_is_cast_again_whenever_the_state_or_the_beams_change():
    """Polled faster than the physics steps, the lidar returns the scan it made at this state; a
    step, a teleport (no step) and new settings each make a new one, and the legacy laser scan in
    between does not stand in for it."""
    sim = Simulation(arena(robots=((1000, 1000, 0),)))
    robot = sim.robots[0]
    scanner = robot.component(LidarScanner)
    first = scanner.scan()
    assert scanner.scan() is first and not first.flags.writeable
    ahead = first[180]

    sim.world.set_free_pose(robot.body, 1.5, 1.0, sim.world.pose(robot.body)[2], 0.0)  # 500 mm on
    teleported = scanner.scan()
    assert teleported is not first and abs(int(ahead) - int(teleported[180]) - 500) <= 2

    legacy = scanner.laser_scan()
    assert legacy is not teleported and scanner.laser_scan() is legacy
    assert scanner.scan() is not legacy and scanner.scan()[180] == teleported[180]

    scanner.configure(90, 0, 90)
    assert len(scanner.scan()) == 90

    before = scanner.scan()
    sim.step()
    assert scanner.scan() is not before
