"""Robot files whose extra colliders reach down to the floor (skids, casters, a chassis bottom):
they glide and weigh their volume's share, so they never brake the robot. A car from such a file
reaches its commanded speed, ahead and back, as fast as the built-in car does.

In-process: the VW controller is driven as its handlers drive it and the true speed is read from
the pose at every step."""

import math

import mujoco
import pytest
from support.worlds import arena_scene, example_robot

from eyesim.core.engine import Simulation
from eyesim.robot.components.vw import VwController
from eyesim.scene import load_robot_type

SPEED = 0.3  # m/s commanded, ahead then back
HOLD = 1.2  # s of each

# EyeSim VR files (model space: X right, Y up, Z forward; size first, then centre). A car with the
# pattern of the real VR Ackermann file: a tall body and a thin front skid 3.5 mm above the floor.
VR_CAR = """drive ACKERMANN_DRIVE
name SkidCar
mass 1.2
collider box 110 70 200 0 60 0
collider box 110 5 30 0 6 100
axel drive 25 -90
axel turn 25 60
wheel drive 50 3600 500 55
wheel turn 50 3600 500 55
"""
# The same car whose skid reaches 2 mm below the floor the wheels stand on.
LOW_SKID_CAR = VR_CAR.replace("name SkidCar", "name LowSkidCar").replace(
    "collider box 110 5 30 0 6 100", "collider box 110 6 30 0 1 100"
)
# A two-wheeler with the VR S4's pattern: body boxes 9 and 10 mm above the floor and a rear caster
# capsule reaching 4 mm below it.
VR_TWO_WHEELER = """drive DIFFERENTIAL_DRIVE
name CasterBot
mass 0.8
collider box 95 74 65 0 46 -50
collider box 95 40 30 0 30 60
collider capsule 10 50 0 21 -60
axis 27 0
wheel 54 3600 1100 45
"""


def robot_file(tmp_path, text: str):
    path = tmp_path / "robot.robi"
    path.write_text(text)
    return load_robot_type(path)


def speed_profile(robot_type) -> tuple[Simulation, list[tuple[float, float]]]:
    """(time s, true speed m/s along the heading) at every step: SPEED ahead for HOLD, then back."""
    sim = Simulation(arena_scene([(robot_type, (1500, 1500, 0))], size=3000))
    robot = sim.robots[0]
    vw = robot.component(VwController)
    dt = sim.step_us / 1e6
    profile = []
    for target in (SPEED, -SPEED):
        vw.set_speed(target, 0.0)
        for _ in range(round(HOLD / dt)):
            x, y, _, phi = robot.pose()
            sim.step()
            x2, y2, _, _ = robot.pose()
            profile.append((sim.world.time, ((x2 - x) * math.cos(phi) + (y2 - y) * math.sin(phi)) / dt))
    return sim, profile


def reaches(profile, target: float, after: float) -> float:
    """Seconds from `after` until the speed is within 5 % of `target` and stays there for 0.2 s."""
    samples = [(t, v) for t, v in profile if t > after + 1e-9]
    for i, (t, _) in enumerate(samples):
        window = [v for t2, v in samples[i:] if t2 <= t + 0.2]
        if all(abs(v - target) <= 0.05 * abs(target) for v in window):
            return t - after
    return math.inf


def times(profile) -> tuple[float, float]:
    return reaches(profile, SPEED, 0.0), reaches(profile, -SPEED, HOLD)


@pytest.fixture(scope="module")
def car_times():
    return times(speed_profile(example_robot("Car"))[1])


@pytest.mark.parametrize("text", [VR_CAR, LOW_SKID_CAR], ids=["skid above the floor", "skid below the floor"])
def test_a_car_with_a_skid_collider_speeds_up_and_reverses_as_fast_as_the_built_in_car(tmp_path, text, car_times):
    ahead, back = times(speed_profile(robot_file(tmp_path, text))[1])
    assert ahead <= car_times[0] + 0.05, (ahead, car_times)
    assert back <= car_times[1] + 0.05, (back, car_times)


def test_a_two_wheeler_on_a_caster_collider_reaches_its_speed_both_ways(tmp_path):
    robot_type = robot_file(tmp_path, VR_TWO_WHEELER)
    _, profile = speed_profile(robot_type)
    ahead, back = times(profile)
    ramp = SPEED / 1.0  # the VW controller ramps at 1 m/s^2
    assert ahead <= ramp + 0.15 and back <= 2 * ramp + 0.15, (ahead, back)


def test_low_colliders_glide_are_raised_to_the_floor_and_weigh_their_volume(tmp_path):
    robot_type = robot_file(tmp_path, VR_TWO_WHEELER)
    sim = Simulation(arena_scene([(robot_type, (1500, 1500, 0))], size=3000))
    model = sim.world.model
    geoms = [
        g
        for g in range(model.ngeom)
        if (mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, g) or "").startswith("robot1/hull")
    ]
    assert len(geoms) == 3
    for g in geoms:  # all three reach below the 12 mm chassis clearance
        assert list(model.geom_friction[g]) == [0, 0, 0] and model.geom_condim[g] == 1
    capsule = geoms[2]  # 50 mm tall about z = 21 mm: raised from 4 mm below the floor to 1 mm above it
    bottom = model.geom_pos[capsule][2] - model.geom_size[capsule][0] - model.geom_size[capsule][1]
    assert bottom == pytest.approx(0.001)
    # The hull's centre of mass is its colliders' centroid by volume (not the mean of their centres).
    volumes = [0.095 * 0.074 * 0.065, 0.095 * 0.040 * 0.030, math.pi * 0.01**2 * 0.03 + 4 / 3 * math.pi * 0.01**3]
    centres = [model.geom_pos[g] for g in geoms]
    expected = sum(v * c for v, c in zip(volumes, centres)) / sum(volumes)
    hull = sim.world.body_id("robot1")
    assert model.body_ipos[hull] == pytest.approx(expected, abs=1e-6)
