"""Which renderer draws the process's camera images: OpenGL when a context can be made, else the
CPU ray caster. Chosen once per process, on the first camera use (on the render thread), and
announced in one line on stderr."""

from __future__ import annotations

import logging
import os
import sys
import threading

from eyesim.physics import render_gl
from eyesim.physics.render_raycast import RayCastRenderer

log = logging.getLogger("eyesim")

# MUJOCO_GL values that switch OpenGL off (as MuJoCo reads them).
GL_OFF = ("disable", "disabled", "off", "false", "0")

_lock = threading.Lock()
_renderer = None


def camera_renderer():
    """The process's renderer: OpenGL when a context can be made, else the ray caster. Chosen and
    used on the render thread (render_worker.py): an OpenGL renderer draws on the thread that made it."""
    global _renderer
    with _lock:
        if _renderer is None:
            _renderer = _choose()
        return _renderer


def close_renderer() -> None:
    """Free the process's renderer (the render thread calls it as the process ends)."""
    global _renderer
    with _lock:
        if _renderer is not None and hasattr(_renderer, "close"):
            _renderer.close()
        _renderer = None


def _choose():
    requested = os.environ.get("MUJOCO_GL", "").strip().lower()
    if requested in GL_OFF:
        _notice(f"cameras use the CPU ray caster (MUJOCO_GL={requested})")
        return RayCastRenderer()
    try:
        backend = render_gl.choose_backend(requested)
        renderer = render_gl.GlRenderer(backend)
    except render_gl.NoOpenGL as error:
        _notice(f"no OpenGL context ({error}); cameras use the CPU ray caster")
        return RayCastRenderer()
    log.info("cameras render with OpenGL (%s)", backend)
    return renderer


def _notice(text: str) -> None:
    print(f"eyesim: {text}", file=sys.stderr, flush=True)
