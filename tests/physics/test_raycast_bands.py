"""The ray caster draws an image in bands of rows and lets the simulation thread run between them
(a whole-image numpy step once held it for up to 66 ms at 5 megapixels): the picture is the same
pixel for pixel as drawn in one piece, and another program is served while a 5-megapixel frame is
drawn, band after band."""

from __future__ import annotations

import dataclasses
import threading

import numpy as np
import pytest
from support.client import ProgramClient
from support.scenes import arena, coloured_scene
from support.simulator import running_simulation

from eyesim.core.engine import Simulation
from eyesim.physics import render_raycast, renderer_choice
from eyesim.physics.render_raycast import RayCastRenderer
from eyesim.parts.camera.component import Camera

CAM5MP = 5
ROBOTS = ((600, 600, 30), (1200, 900, 100), (700, 1300, 200))


def room(tmp_path, fisheye: bool = False, texture: bool = False) -> Simulation:
    """The cameras' coloured room (support/scenes.py), with fisheye cameras if asked."""
    s4 = arena().robot_types["S4"]
    if fisheye:
        s4 = dataclasses.replace(s4, camera=dataclasses.replace(s4.camera, fisheye=True, fov=150))
    return Simulation(coloured_scene(tmp_path, s4, ROBOTS, texture))


def views(sim: Simulation, width: int, height: int):
    for robot in sim.robots:
        camera = robot.component(Camera)
        for camera.pan, camera.tilt in ((0, 0), (0, -25), (70, 10), (180, -5)):
            yield camera.view(width, height)


@pytest.mark.parametrize("fisheye, texture", [(False, False), (False, True), (True, False), (True, True)])
def test_an_image_drawn_in_bands_is_the_image_drawn_whole(tmp_path, fisheye, texture):
    sim = room(tmp_path, fisheye, texture)
    pictures = 0
    for view in views(sim, 333, 77):
        whole = RayCastRenderer(slice_pixels=333 * 77).render(sim.world, view)
        pictures += len(np.unique(whole.reshape(-1, 3), axis=0)) >= 2  # not just a wall close up
        for slice_pixels in (1000, 333 * 5, 1):  # bands of 3, 5 and 1 rows, the last one shorter
            assert np.array_equal(RayCastRenderer(slice_pixels).render(sim.world, view), whole), slice_pixels
    assert pictures >= 8


def test_mujocos_ray_cast_in_bands_is_the_image_drawn_whole(tmp_path, monkeypatch):
    """Geoms without a shape of the ray caster's own (meshes) make it use MuJoCo's ray cast."""
    monkeypatch.setattr(render_raycast, "SHAPES", ())
    sim = room(tmp_path)
    for view in views(sim, 160, 120):
        whole = RayCastRenderer(slice_pixels=160 * 120).render(sim.world, view)
        assert np.array_equal(RayCastRenderer(slice_pixels=160 * 7).render(sim.world, view), whole)


def test_a_5_megapixel_image_in_bands_is_the_image_drawn_whole(tmp_path):
    sim = room(tmp_path, texture=True)
    view = sim.robots[0].component(Camera).view(2592, 1944)
    banded = RayCastRenderer()
    assert banded.slice_pixels < 2592 * 1944 // 30  # dozens of bands
    assert np.array_equal(banded.render(sim.world, view), RayCastRenderer(2592 * 1944).render(sim.world, view))


class CountingRayCaster(RayCastRenderer):
    """The ray caster, noting at each end of a band how many calls another program had answered."""

    def __init__(self, answered: list):
        super().__init__()
        self.answered = answered
        self.seen_at_bands: list[int] = []

    def between_slices(self) -> None:
        self.seen_at_bands.append(len(self.answered))
        super().between_slices()


def test_another_program_is_served_between_the_bands_of_a_5_megapixel_frame(monkeypatch):
    answered: list[int] = []
    renderer = CountingRayCaster(answered)
    monkeypatch.setattr(renderer_choice, "camera_renderer", lambda: renderer)
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180))), "realtime") as (sim, port):
        camera, other = ProgramClient(port, timeout=120), ProgramClient(port)
        camera.hello("1")
        other.hello("2")
        assert camera.call("CAM_INIT", CAM5MP) == (0, 2592, 1944)
        stop = threading.Event()

        def keep_calling():
            while not stop.is_set():
                answered.append(other.call("PSD_GET", 1)[0])

        caller = threading.Thread(target=keep_calling)
        caller.start()
        try:
            assert camera.call("CAM_GET")[:3] == (0, 2592, 1944)
        finally:
            stop.set()
            caller.join(60)
        bands = renderer.seen_at_bands
        assert len(bands) == -(-1944 // (renderer.slice_pixels // 2592))  # the whole frame, band by band
        served_between = sum(later > earlier for earlier, later in zip(bands, bands[1:]))
        assert served_between >= len(bands) // 2, bands  # the other program went on during the frame
        assert all(distance > 0 for distance in answered)
        camera.close()
        other.close()
