"""Building the MuJoCo world from a scene description: floor, walls, markers, objects, water."""

import mujoco
import numpy as np
import pytest
from PIL import Image

from eyesim.core.clock import Clock
from eyesim.core.engine import Simulation
from eyesim.robot.components.vw import VwController
from eyesim.scene import load_scene
from support.worlds import arena_scene, example_robot


def geom(sim, name: str) -> int:
    return mujoco.mj_name2id(sim.world.model, mujoco.mjtObj.mjOBJ_GEOM, name)


def test_floor_walls_and_markers_come_from_the_scene(tmp_path):
    Image.new("RGB", (40, 20), (200, 30, 30)).save(tmp_path / "floor.png")
    (tmp_path / "room.wld").write_text("floor 3000 2000\nfloor_texture floor.png\n0 0 3000 0 20 250 10 200 30\n")
    (tmp_path / "scene.sim").write_text("world room.wld\nmarker 1000 700 0 255 0\nS4 500 500 0\n")
    sim = Simulation(load_scene(str(tmp_path / "scene.sim")), Clock("deterministic"))
    model = sim.world.model
    floor = geom(sim, "floor")
    assert model.geom_size[floor][:2] == pytest.approx([1.5, 1.0])
    assert model.geom_pos[floor][:2] == pytest.approx([1.5, 1.0])
    texture = model.mat_texid[model.geom_matid[floor]][mujoco.mjtTextureRole.mjTEXROLE_RGB]
    assert (model.tex_width[texture], model.tex_height[texture]) == (40, 20)
    wall = geom(sim, "wall0")
    # 3 m long plus half the thickness at each end, 20 mm thick, 250 mm high, standing on the floor
    assert model.geom_size[wall] == pytest.approx([1.51, 0.01, 0.125])
    assert model.geom_pos[wall] == pytest.approx([1.5, 0.0, 0.125])
    assert model.geom_rgba[wall][:3] == pytest.approx([10 / 255, 200 / 255, 30 / 255])
    marker = geom(sim, "marker0")
    assert model.geom_pos[marker][:2] == pytest.approx([1.0, 0.7])
    assert model.geom_rgba[marker][:3] == pytest.approx([0, 1, 0])
    assert model.geom_contype[marker] == 0 and model.geom_conaffinity[marker] == 0  # nothing bumps into it
    assert sim.water is None


def test_maze_balls_and_crates_are_objects_in_scene_order(tmp_path):
    (tmp_path / "maze.maz").write_text("_____\n|o x|\n|S  |\n|___|\n360\n")
    (tmp_path / "scene.sim").write_text("world maze.maz\nS4 S\nCan 600 600 0\n")
    sim = Simulation(load_scene(str(tmp_path / "scene.sim")), Clock("deterministic"))
    assert [o.type.name for o in sim.objects] == ["Soccer", "Crate", "Can"]
    for thing, placement in zip(sim.objects, sim.scene.objects):
        x, y, z, phi = thing.pose_mm()
        assert (x, y) == pytest.approx((placement.pose.x, placement.pose.y), abs=0.01)
        assert z == pytest.approx(0, abs=0.01)


def test_objects_rest_on_the_floor_with_their_declared_mass():
    scene = arena_scene(objects=[("Can", (500, 500, 0)), ("Soccer", (900, 500, 0)), ("Crate", (1300, 500, 45))])
    sim = Simulation(scene, Clock("deterministic"))
    for _ in range(500):
        sim.step()
    model = sim.world.model
    for thing in sim.objects:
        assert model.body_mass[thing.body] == pytest.approx(thing.type.mass)
        x, y, z, phi = thing.pose_mm()
        assert abs(z) < 1.0  # resting, not sunk in or thrown up
    assert sim.objects[2].pose_mm()[3] == pytest.approx(45, abs=0.1)


def test_a_fixed_object_is_part_of_the_static_world():
    scene = arena_scene(robots=[("S4", (500, 500, 0))], objects=[("Crate1", (900, 500, 0))])
    sim = Simulation(scene, Clock("deterministic"))
    block = sim.objects[0]
    assert sim.world.model.body_jntnum[block.body] == 0  # no joint: it cannot move
    sim.robots[0].component(VwController).straight(1.0, 0.3)
    for _ in range(2500):
        sim.step()
    assert block.pose_mm()[:2] == pytest.approx((900, 500), abs=1e-6)
    # the robot stopped at the block's face (900 - 180), its front 82 mm ahead of its centre
    assert sim.robots[0].pose_mm()[0] + 82 == pytest.approx(720, abs=4)


def test_several_robots_stand_where_the_scene_puts_them():
    poses = [(500, 500, 0), (1500, 500, 90), (1000, 1500, -135)]
    sim = Simulation(arena_scene(robots=[("S4", p) for p in poses]), Clock("deterministic"))
    for _ in range(200):
        sim.step()
    for robot, (x, y, phi) in zip(sim.robots, poses):
        assert robot.pose_mm()[0] == pytest.approx(x, abs=0.5)
        assert robot.pose_mm()[1] == pytest.approx(y, abs=0.5)
        assert robot.pose_mm()[3] == pytest.approx(phi, abs=0.1)


def test_water_fills_a_submarine_scene_to_the_highest_wall():
    scene = arena_scene(robots=[(example_robot("Minnow"), (1500, 1500, 0))], wall_height=1200)
    sim = Simulation(scene, Clock("deterministic"))
    assert sim.water.surface == pytest.approx(1.2)
    assert sim.water.density == 1000


def test_reset_puts_robots_and_objects_back():
    scene = arena_scene(robots=[("S4", (500, 500, 0))], objects=[("Soccer", (800, 500, 0))])
    sim = Simulation(scene, Clock("deterministic"))
    sim.robots[0].component(VwController).straight(0.6, 0.3)
    for _ in range(1500):
        sim.step()
    assert sim.objects[0].pose_mm()[0] > 850
    sim.reset()
    assert sim.robots[0].pose_mm()[:2] == pytest.approx((500, 500), abs=1e-6)
    assert sim.objects[0].pose_mm()[:2] == pytest.approx((800, 500), abs=1e-6)
    assert np.all(sim.world.data.ctrl == 0)
