"""What the viewer draws for the scene setting VIS: each robot's PSD beams and its last lidar scan,
and the camera images programs took (docs/viewer-channel.md)."""

from __future__ import annotations

import numpy as np

from eyesim.robot.components.camera import Camera
from eyesim.robot.components.lidar import LidarScanner
from eyesim.robot.components.psd import MAX_RANGE_MM, PsdSensor

PRECISION = 3  # decimals of a metre: millimetres are plenty for a line on the screen


def sensor_rays(robots) -> list[dict]:
    """Per robot and sensor kind: the beams' common origin (PSDs: one entry each, with the PSD's
    id) and the points where they end (m, world frame); a beam that hits nothing ends at the
    sensor's range."""
    rays = []
    for robot in robots:
        for sensor in robot.components_of(PsdSensor):
            origin, direction, hit = sensor.beam()
            end = origin + direction * (hit if hit is not None else MAX_RANGE_MM / 1000)
            rays.append({"robot": robot.id, "kind": "psd", "psd": sensor.id, "origin": _rounded(origin),
                         "ends": _rounded(end)})
        scanner = robot.component(LidarScanner)
        if scanner is not None and scanner.last_scan is not None:
            origin, directions, distances = scanner.last_scan
            ends = origin + directions * (distances[:, None] / 1000.0)
            rays.append({"robot": robot.id, "kind": "lidar", "origin": _rounded(origin),
                         "ends": _rounded(ends.reshape(-1))})
    return rays


def camera_images(robots, sent: dict[int, int]) -> list[dict]:
    """`camera` events for the images taken since the last call (`sent`: robot id -> image count)."""
    events = []
    for robot in robots:
        camera = robot.component(Camera)
        if camera is not None and camera.image is not None and sent.get(robot.id) != camera.image_count:
            sent[robot.id] = camera.image_count
            events.append({"type": "camera", "robot": robot.id, "pixels": camera.image})
    return events


def _rounded(values: np.ndarray) -> list[float]:
    return np.round(values, PRECISION).tolist()
