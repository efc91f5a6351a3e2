"""Cameras: CAMInit/CAMGet/CAMGetGray from a real C program with either renderer, what the images
show (a red wall, a floor texture, another robot), and the two renderers agreeing."""

import os

import numpy as np
import pytest
from PIL import Image
from support.rooms import square_room, write_scene

RENDERERS = {"opengl": {}, "raycast": {"MUJOCO_GL": "disable"}}


def load(path):
    return np.asarray(Image.open(path))


def snap(tmp_path, programs, run_scene, scene, renderer):
    env = dict(os.environ, **RENDERERS[renderer])
    run = run_scene(scene, {1: programs("camera_snap")}, env=env)
    assert run.returncode == 0, run.stdout + run.stderr
    assert ("ray caster" in run.stderr) == (renderer == "raycast"), run.stderr  # OpenGL really ran here
    return run, load(tmp_path / "camera.ppm"), load(tmp_path / "camera.pgm")


@pytest.mark.parametrize("renderer", RENDERERS)
def test_a_red_wall_ahead_fills_the_centre_and_gray_is_the_average(tmp_path, programs, run_scene, renderer):
    world = square_room() + ["1400 700 1400 1300 10 300 255 0 0"]  # red, 400 mm ahead, 600 mm wide
    scene = write_scene(tmp_path, world, ["S4 1000 1000 0"])
    run, colour, gray = snap(tmp_path, programs, run_scene, scene, renderer)

    assert run.values(1, "before") == [[1]] and run.values(1, "custom") == [[1]]
    assert "CAMGet: the camera is not initialised; call CAMInit first" in run.stderr
    assert "CAMInit: CUSTOM is for LCD images only" in run.stderr
    assert run.values(1, "init") == [[0, 320, 240, 76800, 230400]]
    assert run.values(1, "get") == [[0, 0]] and run.values(1, "saved") == [[0, 0]]
    assert run.values(1, "release") == [[0, 1]]

    assert colour.shape == (240, 320, 3) and gray.shape == (240, 320)
    centre = colour[60:180, 120:200].reshape(-1, 3).astype(int)
    assert (centre[:, 0] > 200).all() and (centre[:, 1:] < 40).all()  # the wall faces the camera: pure red
    assert (colour[230, :, :] > 150).all()  # the light grey floor below it
    expected = colour.astype(int).sum(axis=2) // 3  # CAMGetGray = (R + G + B) / 3, as IPCol2Gray
    assert (gray == expected).mean() > 0.999 and np.abs(gray - expected).max() <= 1


@pytest.mark.parametrize("renderer", RENDERERS)
def test_the_floor_texture_and_another_robot_show(tmp_path, programs, run_scene, renderer):
    texture = np.zeros((64, 64, 3), dtype=np.uint8)
    texture[:32] = (255, 0, 255)  # the image's top half: the north half of the floor
    texture[32:] = (0, 255, 0)
    Image.fromarray(texture).save(tmp_path / "floor.png")
    world = square_room() + ["floor_texture floor.png"]
    # Robot 1 at the south end looks north over the green half towards the magenta one; robot 2
    # (S4 blue 40 90 200, its side turned to robot 1) stands 600 mm ahead on the green half.
    scene = write_scene(tmp_path, world, ["S4 1000 150 90", "S4 1000 750 0"])
    run, colour, _ = snap(tmp_path, programs, run_scene, scene, renderer)

    assert tuple(colour[235, 160]) == (0, 255, 0)  # the floor just ahead: green, fully lit
    far_floor = colour[135:145, 10:60].reshape(-1, 3)  # below the far wall, beside robot 2
    assert (far_floor == (255, 0, 255)).all(axis=1).mean() > 0.9
    robot = colour[115:155, 150:170].reshape(-1, 3).astype(int)  # robot 2's flank, at camera height
    assert (np.abs(robot - (40, 90, 200)) <= 12).all(axis=1).mean() > 0.9
