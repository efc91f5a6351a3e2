"""What the viewer gets from the sensors (docs/viewer-channel.md): rays in snapshots with the scene
setting VIS, and a robot's last camera image as an event while a browser is connected."""

import dataclasses

import numpy as np
from support.scenes import arena

from eyesim.core.engine import Simulation
from eyesim.parts.camera.component import Camera
from eyesim.parts.lidar.component import LidarScanner
from eyesim.parts.psd.component import PsdSensor
from eyesim.scene.description import Settings
from eyesim.viewer.messages import snapshot


class Browser:
    wants_lcd = True

    def __init__(self):
        self.events = []
        self.snapshots = []

    def on_event(self, message):
        self.events.append(message)

    def on_snapshot(self, message):
        self.snapshots.append(message)


def simulation(vis: bool) -> Simulation:
    scene = arena(robots=((500, 500, 0), (1500, 1500, 90)))
    return Simulation(dataclasses.replace(scene, settings=Settings(vis=vis)))


def test_snapshots_carry_the_sensor_rays_only_with_vis():
    assert "rays" not in snapshot(simulation(vis=False))
    sim = simulation(vis=True)
    rays = snapshot(sim)["rays"]
    psd = [r for r in rays if r["kind"] == "psd"]
    assert len(psd) == 8 and not [r for r in rays if r["kind"] == "lidar"]  # no scan taken yet
    assert [r["psd"] for r in psd if r["robot"] == 1] == [1, 2, 3, 4]  # S4's PSDs, PSD_FRONT first
    front = next(r for r in psd if r["robot"] == 1)
    length = np.linalg.norm(np.subtract(front["ends"], front["origin"]))
    assert abs(length * 1000 - sim.robots[0].components_of(PsdSensor)[0].distance_mm()) < 2

    scan = sim.robots[1].component(LidarScanner).scan()
    lidar = [r for r in snapshot(sim)["rays"] if r["kind"] == "lidar"]
    assert [r["robot"] for r in lidar] == [2] and len(lidar[0]["ends"]) == 3 * 360
    ends = np.reshape(lidar[0]["ends"], (-1, 3))
    lengths = np.linalg.norm(ends - lidar[0]["origin"], axis=1) * 1000
    assert np.abs(lengths - scan).max() < 2


def test_the_last_camera_image_goes_to_a_connected_browser_once():
    sim = simulation(vis=False)
    browser = Browser()
    sim.events.subscribe(browser)
    sim.run(until=0.05)
    assert not [e for e in browser.events if e["type"] == "camera"]  # no program took a picture
    camera = sim.robots[0].component(Camera)
    camera.start(160, 120)
    image = camera.capture()
    sim.run(until=0.1)
    sim.run(until=0.15)
    shown = [e for e in browser.events if e["type"] == "camera"]
    assert len(shown) == 1 and shown[0]["robot"] == 1 and shown[0]["pixels"] is image
