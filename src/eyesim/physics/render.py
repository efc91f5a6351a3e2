"""Camera images of the MuJoCo world: what a view is and how it is lit, shared by both renderers.

Two renderers draw the same picture: MuJoCo's OpenGL renderer (render_gl.py) wherever an OpenGL
context can be made, and a CPU ray caster (render_raycast.py) everywhere else; which one a process
uses is renderer_choice.py's. The simulator draws on its render thread (render_worker.py), off the
simulation thread."""

from __future__ import annotations

import logging
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

log = logging.getLogger("eyesim")

# Lighting shared by both renderers, so they agree: a light at the camera (ambient + diffuse
# along the view direction) and a light from straight above, no specular highlights, no
# shadows. A surface facing the camera head-on, or the floor, shows its own colour.
HEADLIGHT_AMBIENT = 0.5
HEADLIGHT_DIFFUSE = 0.5
TOP_LIGHT_DIFFUSE = 0.5
BACKGROUND = (0, 0, 0)  # what a ray that hits nothing shows
NEAR = 0.005  # m: nearest distance a camera sees
FAR = 50.0  # m


@dataclass(frozen=True)
class View:
    """What a camera sees: its world position (m), unit view direction and unit up vector
    (perpendicular to forward), image size, horizontal field of view, and lens. A fisheye lens
    is equidistant (angle off the axis proportional to the distance from the image centre) with
    an image circle as wide as the image; outside the circle the image is black.
    `own_body` is the camera's robot chassis, which the ray caster looks through."""

    position: tuple[float, float, float]
    forward: tuple[float, float, float]
    up: tuple[float, float, float]
    width: int
    height: int
    fov: float  # degrees, horizontal
    fisheye: bool = False
    own_body: int = -1

    @property
    def right(self) -> np.ndarray:
        return np.cross(self.forward, self.up)


def camera_rays(width: int, height: int, fov: float, fisheye: bool) -> tuple[np.ndarray, np.ndarray]:
    """Unit ray directions of every pixel (row-major, top row first) in the camera frame
    (x right, y up, z forward), and a mask of the pixels inside the lens (all, unless fisheye).
    Not kept: at 5 megapixels these are 120 MB; renderers keep what they need (camera_ray_axes,
    camera_lens)."""
    half = np.radians(fov) / 2
    u = np.arange(width) - (width - 1) / 2  # pixel centres, right positive
    v = (height - 1) / 2 - np.arange(height)  # up positive
    uu, vv = np.meshgrid(u, v)
    if fisheye:
        angle_per_pixel = half / (width / 2)
        radius = np.hypot(uu, vv)
        theta = radius * angle_per_pixel
        inside = radius <= width / 2
        scale = np.where(radius > 0, np.sin(theta) / np.maximum(radius, 1e-12), 0.0)
        rays = np.stack([uu * scale, vv * scale, np.cos(theta)], axis=-1)
    else:
        focal = (width / 2) / np.tan(half)
        rays = np.stack([uu, vv, np.full_like(uu, focal)], axis=-1)
        rays /= np.linalg.norm(rays, axis=-1, keepdims=True)
        inside = np.ones(uu.shape, dtype=bool)
    rays = rays.reshape(-1, 3)
    rays.setflags(write=False)
    inside = inside.reshape(-1)
    inside.setflags(write=False)
    return rays, inside


def camera_ray_axes(width: int, height: int, fov: float, fisheye: bool) -> tuple[np.ndarray, ...]:
    """camera_rays as three contiguous arrays, x, y and z of every pixel's ray, and the lens mask."""
    return _camera_ray_axes(width, height, float(fov), bool(fisheye))


@lru_cache(maxsize=16)
def _camera_ray_axes(width: int, height: int, fov: float, fisheye: bool) -> tuple[np.ndarray, ...]:
    rays, inside = camera_rays(width, height, fov, fisheye)
    axes = tuple(np.ascontiguousarray(rays[:, axis], dtype=np.float32) for axis in range(3)) + (inside,)
    for axis in axes:
        axis.setflags(write=False)
    return axes


def shade(base_rgb: np.ndarray, normals: np.ndarray, forward: np.ndarray) -> np.ndarray:
    """Colours (n, 3) 0..1 lit by the shared lights, for surface normals (n, 3) facing the viewer."""
    light = HEADLIGHT_AMBIENT + HEADLIGHT_DIFFUSE * np.maximum(-dot(normals, forward), 0.0)
    light += TOP_LIGHT_DIFFUSE * np.maximum(normals[:, 2], 0.0)
    return np.minimum(base_rgb * light[:, None], 1.0)


# Products of many 3-vectors with one small matrix or vector, element by element: a BLAS call for
# so thin a product is slower, and on a busy machine far slower (its threads wait for cores).
def times(vectors: np.ndarray, matrix: np.ndarray) -> np.ndarray:
    """vectors (n, 3) @ matrix (3, 3)."""
    return vectors[:, 0, None] * matrix[0] + vectors[:, 1, None] * matrix[1] + vectors[:, 2, None] * matrix[2]


def dot(vectors: np.ndarray, vector) -> np.ndarray:
    """vectors (n, 3) . vector (3,)."""
    return vectors[:, 0] * vector[0] + vectors[:, 1] * vector[1] + vectors[:, 2] * vector[2]


def to_gray(image: np.ndarray) -> np.ndarray:
    """CAMGetGray's conversion, the same as IPCol2Gray's: (R + G + B) / 3, rounded down."""
    total = image[..., 0].astype(np.uint16)  # summed in place: sum(axis=2) widened to 64 bits, 5x slower
    total += image[..., 1]
    total += image[..., 2]
    total //= 3
    return total.astype(np.uint8)
