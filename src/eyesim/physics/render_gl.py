"""Camera images with MuJoCo's OpenGL renderer, headless (EGL, OSMesa) or on a display (GLFW).

PyOpenGL binds itself to one platform for the life of a process, so a backend that fails cannot
be swapped for another. The backend is therefore tried first in a short-lived child process
(`python -m eyesim.physics.render_gl <backend>`), in MuJoCo's order of preference, and only the
first that works is loaded here. A GlRenderer draws on the thread that made it, which owns its
context (the simulator's is the render thread, physics/render_worker.py)."""

from __future__ import annotations

import os
import subprocess
import sys
import weakref
from functools import lru_cache

import mujoco
import numpy as np

from eyesim.physics import render
from eyesim.physics.render import View  # by name: in the renderer's class, `render` is its method

PROBE_TIMEOUT = 60.0  # s a trial child process may take (a loaded machine starts Python slowly)
MAX_TEXTURE_SIDE = 4096  # pixels: the largest intermediate image a fisheye view renders
FISHEYE_OVERSAMPLE = 2.0  # intermediate perspective image size per fisheye image width


class NoOpenGL(Exception):
    """No OpenGL context can be made (the message says why)."""


def candidate_backends(requested: str) -> list[str]:
    """MUJOCO_GL's value if set (MuJoCo reads 'glx' as GLFW), else what may work here, best first."""
    if requested:
        return ["glfw" if requested in ("glx", "enable", "enabled", "on", "true", "1") else requested]
    if sys.platform == "darwin":
        return ["cgl", "glfw"]
    if sys.platform == "win32":
        return ["glfw"]
    display = bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
    return (["glfw"] if display else []) + ["egl", "osmesa"]


def choose_backend(requested: str) -> str:
    """The first backend that can render here; NoOpenGL when none can. A backend MUJOCO_GL names
    is tried too: a GL stack may fail without an exception, or crash (GLFW without a display)."""
    candidates = candidate_backends(requested)
    for backend in candidates:
        if _works(backend):
            return backend
    raise NoOpenGL(f"tried {', '.join(candidates)}")


def _works(backend: str) -> bool:
    env = dict(os.environ, MUJOCO_GL=backend)
    if backend in ("egl", "osmesa"):
        env["PYOPENGL_PLATFORM"] = backend
    try:
        result = subprocess.run(
            [sys.executable, "-m", "eyesim.physics.render_gl", backend],
            env=env,
            capture_output=True,
            timeout=PROBE_TIMEOUT,
        )
    except (OSError, subprocess.TimeoutExpired):
        return False
    return result.returncode == 0


def _context_class(backend: str):
    """MuJoCo's GLContext class of a backend (importing it binds PyOpenGL to that platform)."""
    try:
        if backend == "egl":
            os.environ.setdefault("PYOPENGL_PLATFORM", "egl")
            from mujoco.egl import GLContext
        elif backend == "osmesa":
            os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")
            from mujoco.osmesa import GLContext
        elif backend == "cgl":
            from mujoco.cgl import GLContext
        elif backend == "glfw":
            from mujoco.glfw import GLContext
        else:
            raise NoOpenGL(f"unknown MUJOCO_GL backend {backend!r}")
    except (ImportError, OSError, AttributeError) as error:
        raise NoOpenGL(f"{backend}: {error}") from None
    return GLContext


class _Target:
    """What drawing one world needs in the GL context: MuJoCo's GPU copy of the model and a scene."""

    def __init__(self, world):
        self.world = weakref.ref(world)
        model = world.model
        model.vis.quality.offsamples = 0  # no multisampling: robot cameras do not need it, and it is slow
        self.context = mujoco.MjrContext(model, mujoco.mjtFontScale.mjFONTSCALE_100)
        mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, self.context)
        self.size = (model.vis.global_.offwidth, model.vis.global_.offheight)
        self.scene = mujoco.MjvScene(model, maxgeom=max(1000, 4 * model.ngeom))
        for flag in (
            mujoco.mjtRndFlag.mjRND_SHADOW,
            mujoco.mjtRndFlag.mjRND_REFLECTION,
            mujoco.mjtRndFlag.mjRND_SKYBOX,
            mujoco.mjtRndFlag.mjRND_FOG,
        ):
            self.scene.flags[flag] = 0
        self.option = mujoco.MjvOption()
        self.camera = mujoco.MjvCamera()
        self.camera.type = mujoco.mjtCamera.mjCAMERA_FREE

    def ensure_size(self, width: int, height: int) -> None:
        if width > self.size[0] or height > self.size[1]:
            self.size = (max(width, self.size[0]), max(height, self.size[1]))
            mujoco.mjr_resizeOffscreen(self.size[0], self.size[1], self.context)

    def free(self) -> None:
        self.context.free()


class GlRenderer:
    """Draws views with an OpenGL context it makes on the thread that creates it; every call must
    come from that thread (each makes the context current: a thread may have more than one)."""

    name = "opengl"

    def __init__(self, backend: str):
        self.backend = backend
        self._targets: dict[int, _Target] = {}
        context_class = _context_class(backend)
        try:
            self._gl = context_class(64, 64)
            self._gl.make_current()
        except Exception as error:  # whatever the GL stack raises when it cannot make a context
            raise NoOpenGL(f"{backend}: {error}") from None

    def render(self, world, view: View, data=None) -> np.ndarray:
        """The view's image, (height, width, 3) uint8, top row first; `data`: the physics state to
        draw (a copy of the world's), else the world's own."""
        self._gl.make_current()
        target = self._target(world)
        data = world.data if data is None else data
        if not view.fisheye:
            return self._perspective(world.model, data, target, view, view.width, view.height, view.fov)
        # A fisheye image is resampled from a square pinhole image of the same field of view.
        side = int(min(MAX_TEXTURE_SIDE, round(view.width * FISHEYE_OVERSAMPLE)))
        square = self._perspective(world.model, data, target, view, side, side, view.fov)
        rows, cols, inside = _fisheye_map(view.width, view.height, view.fov, side)
        image = square[rows, cols]
        image[~inside] = render.BACKGROUND
        return image

    def prepare(self, world, width: int, height: int) -> None:
        """Make the world's GPU copy and an image buffer of this size before the first image."""
        self._gl.make_current()
        self._target(world).ensure_size(width, height)

    def close(self) -> None:
        """Free the GPU copies and the context (on the thread that made them)."""
        for target in self._targets.values():
            target.free()
        self._targets.clear()
        self._gl.free()

    def _target(self, world) -> _Target:
        for key, old in list(self._targets.items()):
            if old.world() is None:  # that simulation is gone: free its GPU copy here, on the GL thread
                old.free()
                del self._targets[key]
        target = self._targets.get(id(world))
        if target is None or target.world() is not world:
            target = self._targets[id(world)] = _Target(world)
        return target

    def _perspective(self, model, data, target: _Target, view: View, width: int, height: int, fov: float) -> np.ndarray:
        """A pinhole image of `fov` degrees across its width."""
        target.ensure_size(width, height)
        scene = target.scene
        mujoco.mjv_updateScene(model, data, target.option, None, target.camera, mujoco.mjtCatBit.mjCAT_ALL, scene)
        for geom in scene.geoms[: scene.ngeom]:
            if geom.objtype == mujoco.mjtObj.mjOBJ_GEOM and model.geom_bodyid[geom.objid] == view.own_body:
                geom.pos[2] = -2 * render.FAR  # out of sight: the camera looks past its own chassis
        top = render.NEAR * np.tan(np.radians(fov) / 2) * height / width
        for camera in scene.camera:  # both eyes at the lens: a mono image
            camera.pos[:] = view.position
            camera.forward[:] = view.forward
            camera.up[:] = view.up
            camera.frustum_near, camera.frustum_far = render.NEAR, render.FAR
            camera.frustum_top, camera.frustum_bottom = top, -top
            camera.frustum_center, camera.frustum_width = 0.0, 0.0  # width follows the aspect ratio
            camera.orthographic = 0
        _set_lights(scene, view)
        viewport = mujoco.MjrRect(0, 0, width, height)
        mujoco.mjr_render(viewport, scene, target.context)
        image = np.empty((height, width, 3), dtype=np.uint8)
        mujoco.mjr_readPixels(image, None, viewport, target.context)
        return image[::-1].copy()  # OpenGL's first row is the bottom one


def _set_lights(scene, view: View) -> None:
    """The shared lights of render.py, in place of the model's: a headlight at the lens and a
    light from straight above."""
    head, top = scene.lights[0], scene.lights[1]
    for light in (head, top):
        light.type = mujoco.mjtLightType.mjLIGHT_DIRECTIONAL
        light.castshadow = 0
        light.specular[:] = 0.0
    head.headlight, head.pos[:], head.dir[:] = 1, view.position, view.forward
    head.ambient[:], head.diffuse[:] = render.HEADLIGHT_AMBIENT, render.HEADLIGHT_DIFFUSE
    top.headlight, top.pos[:], top.dir[:] = 0, (0.0, 0.0, 10.0), (0.0, 0.0, -1.0)
    top.ambient[:], top.diffuse[:] = 0.0, render.TOP_LIGHT_DIFFUSE
    scene.nlight = 2


@lru_cache(maxsize=8)
def _fisheye_map(width: int, height: int, fov: float, side: int):
    """Pixel (row, column) of a square perspective image of `fov` degrees for every fisheye
    pixel, and the mask of pixels inside the lens circle."""
    rays, inside = render.camera_rays(width, height, fov, True)
    focal = (side / 2) / np.tan(np.radians(fov) / 2)
    z = np.maximum(rays[:, 2], 1e-6)
    cols = np.clip(np.rint(rays[:, 0] / z * focal + (side - 1) / 2), 0, side - 1).astype(np.intp)
    rows = np.clip(np.rint((side - 1) / 2 - rays[:, 1] / z * focal), 0, side - 1).astype(np.intp)
    return rows.reshape(height, width), cols.reshape(height, width), inside.reshape(height, width)


def _probe(backend: str) -> int:
    """Child-process check: can this backend make a context and draw a frame?"""
    spec = mujoco.MjSpec()
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.1, 0.1, 0.1], pos=[1, 0, 0])
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    gl = _context_class(backend)(64, 64)
    gl.make_current()
    context = mujoco.MjrContext(model, mujoco.mjtFontScale.mjFONTSCALE_100)
    mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, context)
    scene = mujoco.MjvScene(model, maxgeom=100)
    mujoco.mjv_updateScene(model, data, mujoco.MjvOption(), None, mujoco.MjvCamera(), mujoco.mjtCatBit.mjCAT_ALL, scene)
    mujoco.mjr_render(mujoco.MjrRect(0, 0, 8, 8), scene, context)
    context.free()
    gl.free()
    return 0


if __name__ == "__main__":
    sys.exit(_probe(sys.argv[1]))
