"""PSDGet/PSDGetRaw from a real C program: distances to walls of known geometry, the sensor curve,
seeded noise from the scene or the command line, and errors; the noise settings in scene files."""

import math
import statistics

from support.rooms import square_room, write_scene
from support.scenes import arena

from eyesim.core.engine import Simulation
from eyesim.parts.psd.component import RAW_OFFSET, RAW_SCALE, PsdSensor, raw_value
from eyesim.scene.description import Settings
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.json_format import dumps, parse_json, to_json
from eyesim.scene.sim import parse_sim, write_sim

ROOM = 2000
INNER = (5.0, ROOM - 5.0)  # the walls' inner faces (10 mm thick, centred on the edges)
# S4's PSDs (eyesim/data/robots/S4.robi): id -> (x, y, heading) in the robot frame
S4_PSDS = {1: (90, 0, 0), 2: (0, 75, 90), 3: (0, -75, -90), 4: (-90, 0, 180)}


def distance_to_room_wall(x: float, y: float, heading_deg: float) -> float:
    """Distance from (x, y) inside the room along a heading to the first inner wall face."""
    dx, dy = math.cos(math.radians(heading_deg)), math.sin(math.radians(heading_deg))
    candidates = []
    for start, delta in ((x, dx), (y, dy)):
        for face in INNER:
            if abs(delta) > 1e-12 and (face - start) / delta > 0:
                candidates.append((face - start) / delta)
    return min(candidates)


def expected_psd(pose: tuple[float, float, float], psd: int) -> float:
    x, y, phi = pose
    sx, sy, heading = S4_PSDS[psd]
    c, s = math.cos(math.radians(phi)), math.sin(math.radians(phi))
    return distance_to_room_wall(x + c * sx - s * sy, y + s * sx + c * sy, phi + heading)


def test_every_s4_psd_measures_the_wall_it_faces(tmp_path, programs, run_scene):
    poses = {1: (700, 600, 0), 2: (1300, 1400, 30)}  # robot 2 is turned: its beams meet the walls at angles
    scene = write_scene(tmp_path, square_room(ROOM), [f"S4 {x} {y} {phi}" for x, y, phi in poses.values()])
    report = programs("psd_report")
    run = run_scene(scene, {1: report, 2: report})
    assert run.returncode == 0, run.stdout + run.stderr
    for robot, pose in poses.items():
        x, y, phi = run.values(robot, "pose")[0]
        assert math.hypot(x - pose[0], y - pose[1]) <= 2 and abs(phi - pose[2]) <= 1  # it stood still
        for when in ("start", "settled"):
            readings = {psd: (mm, raw) for psd, mm, raw in run.values(robot, when)}
            assert sorted(readings) == [1, 2, 3, 4]
            for psd, (mm, raw) in readings.items():
                assert abs(mm - expected_psd(pose, psd)) <= 5, (robot, when, psd, mm, expected_psd(pose, psd))
                assert raw == min(1023, round(RAW_SCALE / (mm + RAW_OFFSET)))
    missing = run.values(1, "missing")[0]
    assert missing == [-1, -1]
    assert "PSDGet: robot 1 has no PSD 7 (it has [1, 2, 3, 4])" in run.stderr


def test_noise_is_gaussian_seeded_and_off_by_default(tmp_path, programs, run_scene):
    noise = programs("psd_noise")
    exact = expected_psd((1000, 1000, 0), 1)

    def readings(scene, *args):
        run = run_scene(scene, {1: noise}, *args)
        assert run.returncode == 0, run.stderr
        return [value for (value,) in run.values(1, "front")]

    quiet = write_scene(tmp_path, square_room(ROOM), ["S4 1000 1000 0"])
    assert set(readings(quiet)) == {round(exact)}

    noisy = write_scene(tmp_path, square_room(ROOM), ["S4 1000 1000 0"], settings="PSDNOISE=20 SEED=7")
    first, again = readings(noisy), readings(noisy)
    assert first == again  # seeded: a scene repeats exactly
    assert abs(statistics.fmean(first) - exact) < 6  # 200 samples: the mean is within 3 standard errors
    assert 14 < statistics.stdev(first) < 26

    other_seed = readings(noisy, "--seed", "8")
    assert other_seed != first
    from_command_line = readings(quiet, "--psd-noise", "5")
    assert 3 < statistics.stdev(from_command_line) < 7


def test_the_noise_settings_are_read_written_and_checked():
    diagnostics = Diagnostics()
    document = parse_sim("settings VIS psdnoise=12.5 Seed=42\n", "a.sim", diagnostics)
    assert not diagnostics.items
    assert document.settings == Settings(vis=True, psd_noise=12.5, seed=42)
    again = parse_sim(write_sim(document), "b.sim", Diagnostics())
    assert again.settings == document.settings
    kind, from_json = parse_json(dumps(to_json("scene", document)), "a.json", Diagnostics())
    assert kind == "scene" and from_json.settings == document.settings

    diagnostics = Diagnostics()
    parse_sim("settings PSDNOISE=-1 SEED=x PSDNOISE\n", "c.sim", diagnostics)
    messages = [str(d) for d in diagnostics.items]
    assert messages == [
        "c.sim:1:10: error: settings: PSDNOISE expects a standard deviation in mm >= 0, found '-1'",
        "c.sim:1:22: error: settings: SEED expects a whole number, found 'x'",
        "c.sim:1:29: error: settings: PSDNOISE needs a value: PSDNOISE=<a standard deviation in mm >= 0>",
    ]


def test_a_reading_is_cast_once_per_state_and_the_noise_drawn_for_every_reading(monkeypatch):
    """Polled faster than the physics steps, a PSD casts its beam once for the state of the world
    and reads that hit again (it would come out the same); a teleport (no step) or a step casts
    anew; the noise is still drawn for every reading."""
    casts = []
    real_beam = PsdSensor.beam

    def counted_beam(sensor):
        casts.append(sensor.id)
        return real_beam(sensor)

    monkeypatch.setattr(PsdSensor, "beam", counted_beam)
    sim = Simulation(arena(robots=((1000, 1000, 0),)))
    robot = sim.robots[0]
    front = next(s for s in robot.components_of(PsdSensor) if s.id == 1)
    first = front.distance_mm()
    assert [front.distance_mm() for _ in range(5)] == [first] * 5 and front.raw() == raw_value(first)
    assert casts == [1]

    sim.world.set_free_pose(robot.body, 1.5, 1.0, sim.world.pose(robot.body)[2], 0.0)  # 500 mm on
    assert abs(first - front.distance_mm() - 500) <= 2 and casts == [1, 1]
    sim.step()
    front.distance_mm()
    assert casts == [1, 1, 1]

    front.set_noise(20, seed=7)
    noisy = [front.distance_mm() for _ in range(50)]
    assert len(set(noisy)) > 10 and casts == [1, 1, 1, 1]  # one cast after the reset, fresh noise each time
