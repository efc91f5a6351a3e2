"""The two camera renderers: OpenGL runs here, the ray caster takes over without it, both draw the
same picture; fisheye lenses, servo-driven pan, and no rendering unless a program asks."""

import dataclasses
import os
import subprocess
import sys

import numpy as np
import pytest
from support.client import ProgramClient
from support.scenes import BLUE, GREEN, ORANGE, RED, arena, coloured_scene
from support.simulator import running_simulation

from eyesim.core.engine import Simulation
from eyesim.physics import render_gl, renderer_choice
from eyesim.physics.render_raycast import RayCastRenderer
from eyesim.parts.camera.component import Camera


@pytest.fixture(scope="module")
def opengl():
    """An OpenGL renderer: this machine must be able to make one (EGL or OSMesa, software)."""
    backend = render_gl.choose_backend("")
    assert backend in ("egl", "osmesa", "glfw")
    return render_gl.GlRenderer(backend)


def coloured_room(
    tmp_path, robot_type=None, robots=((600, 600, 30), (1200, 900, 100), (700, 1300, 200)), texture=False
):
    return Simulation(coloured_scene(tmp_path, robot_type, robots, texture))


def difference(first: np.ndarray, second: np.ndarray, block: int = 1) -> tuple[float, float]:
    """Mean absolute channel difference, and the share of pixels (or blocks of pixels, averaged)
    differing by more than 40."""
    height, width = first.shape[0] // block, first.shape[1] // block

    def blocks(image):
        return image[: height * block, : width * block].reshape(height, block, width, block, 3).mean(axis=(1, 3))

    diff = np.abs(blocks(first.astype(float)) - blocks(second.astype(float)))
    return diff.mean(), (diff.max(axis=2) > 40).mean()


VIEWS = [(0, 0), (0, -25), (70, 10), (180, -5)]  # camera pan, tilt (degrees)


@pytest.mark.parametrize("pan, tilt", VIEWS)
def test_both_renderers_draw_the_same_picture(tmp_path, opengl, pan, tilt):
    sim = coloured_room(tmp_path)
    ray_caster = RayCastRenderer()
    for robot in sim.robots:
        camera = robot.component(Camera)
        camera.pan, camera.tilt = pan, tilt
        view = camera.view(160, 120)
        gl, cast = opengl.render(sim.world, view), ray_caster.render(sim.world, view)
        mean, outliers = difference(gl, cast)
        assert mean < 1.5 and outliers < 0.01, (robot.id, mean, outliers)  # edges may fall on either side
        assert len(np.unique(gl.reshape(-1, 3), axis=0)) >= 2  # not a blank picture


@pytest.mark.parametrize("pan, tilt", VIEWS)
def test_both_renderers_show_the_floor_texture_alike(tmp_path, opengl, pan, tilt):
    """OpenGL filters textures (smooth, blurred with distance), the ray caster takes the nearest
    texel: the pictures agree in 8 x 8 pixel blocks."""
    sim = coloured_room(tmp_path, texture=True)
    for robot in sim.robots:
        camera = robot.component(Camera)
        camera.pan, camera.tilt = pan, tilt
        view = camera.view(160, 120)
        mean, outliers = difference(opengl.render(sim.world, view), RayCastRenderer().render(sim.world, view), 8)
        assert mean < 6 and outliers < 0.05, (robot.id, mean, outliers)


def test_a_fisheye_image_is_round_and_both_renderers_agree(tmp_path, opengl):
    s4 = arena().robot_types["S4"]
    fisheye = dataclasses.replace(s4, camera=dataclasses.replace(s4.camera, fisheye=True, fov=150))
    sim = coloured_room(tmp_path, fisheye)
    view = sim.robots[0].component(Camera).view(160, 120)
    gl, cast = opengl.render(sim.world, view), RayCastRenderer().render(sim.world, view)
    for image in (gl, cast):
        assert (image[0, 0] == 0).all() and (image[-1, -1] == 0).all()  # corners lie outside the lens circle
        assert image[60, 80].any()
    mean, outliers = difference(gl, cast)
    assert mean < 2 and outliers < 0.02, (mean, outliers)


def test_servos_pan_and_tilt_the_camera(tmp_path):
    s4 = arena().robot_types["S4"]
    servo_camera = dataclasses.replace(
        s4.camera, pan_servo=1, tilt_servo=2, pan_range=(-90.0, 90.0), tilt_range=(-80.0, 40.0)
    )
    scene = coloured_scene(tmp_path, dataclasses.replace(s4, camera=servo_camera), robots=((1000, 1000, 0),))
    with running_simulation(scene, "deterministic", expect=(1,)) as (sim, port):
        client = ProgramClient(port)
        client.hello()
        client.call("CAM_INIT", 0)

        def centre_after(servo: int, position: int) -> tuple:
            client.call("SERVO_SET", servo, position)
            client.call("OS_WAIT", 600)  # a servo turns 300 degrees per second
            _, width, height, pixels = client.call("CAM_GET")
            image = np.frombuffer(pixels, dtype=np.uint8).reshape(height, width, 3)
            return tuple(int(v) for v in image[height // 2, width // 2])

        assert centre_after(1, 128) == GREEN  # pan 0.35 degrees: east, the green wall
        assert centre_after(1, 255) == BLUE  # fully left: north, the blue wall
        assert centre_after(1, 0) == ORANGE  # fully right: south, the low orange wall before the red one
        floor = centre_after(2, 0)  # tilted 80 degrees down: the floor just ahead
        assert floor not in (RED, GREEN, BLUE, ORANGE) and len(set(floor)) == 1  # grey
        camera = sim.robots[0].component(Camera)
        assert camera.pan == pytest.approx(-90) and camera.tilt == pytest.approx(-80)


def test_no_image_is_rendered_unless_a_program_asks(monkeypatch):
    calls = []

    class Counting:
        def render(self, world, view, data=None):
            calls.append(view)
            return np.zeros((view.height, view.width, 3), dtype=np.uint8)

    monkeypatch.setattr(renderer_choice, "camera_renderer", lambda: Counting())
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 0))), "deterministic", expect=(1,)) as (sim, port):
        client = ProgramClient(port)
        client.hello("1")
        client.call("OS_WAIT", 200)
        assert calls == []
        client.call("CAM_INIT", 0)
        assert calls == []
        result, width, height, pixels = client.call("CAM_GET")
        assert (result, width, height, len(pixels)) == (0, 160, 120, 160 * 120 * 3)
        assert [(v.width, v.height) for v in calls] == [(160, 120)]


def test_without_opengl_the_ray_caster_takes_over_with_a_notice():
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env["MUJOCO_GL"] = "glfw"  # GLFW cannot make a context without a display
    result = subprocess.run(
        [
            sys.executable,
            "-c",
            "from eyesim.physics import renderer_choice; print(renderer_choice.camera_renderer().name)",
        ],
        capture_output=True,
        text=True,
        env=env,
    )
    assert result.stdout.strip() == "raycast"
    notices = [line for line in result.stderr.splitlines() if line.startswith("eyesim:")]
    assert notices == ["eyesim: no OpenGL context (tried glfw); cameras use the CPU ray caster"]
