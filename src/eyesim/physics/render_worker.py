"""The process's render thread: camera images are drawn here, never on the simulation thread.

The simulation thread also serves every program's socket, so a frame drawn there (tens of ms at 5
megapixels, and about a second to prepare OpenGL the first time) made every other program wait.
Instead a camera takes a `Frame`: on the simulation thread, a copy of the physics state at the
time of the request (mj_copyData into a spare MjData kept for the world: tens of microseconds) and
the camera's view; here, the image drawn from that copy and turned into its reply. The image is
therefore the same whenever it is drawn, which keeps deterministic runs bit-identical.

One thread for the whole process, started by the first camera: it chooses the renderer
(renderer_choice.camera_renderer; the OpenGL probe and context are made here, and the context stays with
this thread) and draws frames in the order they come. A thread per camera or per CAMInit gave the
allocator an arena per thread whose freed memory stayed. The thread is not a daemon: when the
main thread ends it finishes what it is doing, frees the renderer and ends before the interpreter
tears down (a daemon thread still making a context at exit crashed the process)."""

from __future__ import annotations

import logging
import queue
import threading
import traceback
import weakref
from typing import Callable

import mujoco
import numpy as np

from eyesim.physics import render, renderer_choice

log = logging.getLogger("eyesim")

EXIT_CHECK = 0.2  # s between looks at whether the main thread has ended, while idle


class Frame:
    """One camera image to draw: the state of the world when it was asked for, the view, and what
    to make of the image (`finish(image)`, run on the render thread: the reply, say). Once done,
    `image` and `result` are set, or `error` (a traceback) if drawing failed."""

    def __init__(self, world, view: render.View, finish: Callable[[np.ndarray], object]):
        self.world, self.view, self.finish = world, view, finish
        self.data = _copy_state(world)
        self.image: np.ndarray | None = None
        self.result: object = None
        self.error: str | None = None
        self.cancelled = False  # nobody waits for it any more: not drawn if not begun
        self._done = threading.Event()
        self._lock = threading.Lock()
        self._callbacks: list[Callable[[], None]] = []

    def done(self) -> bool:
        return self._done.is_set()

    def wait(self) -> None:
        self._done.wait()

    def when_done(self, callback: Callable[[], None]) -> None:
        """Call `callback()` once the frame is done: on the render thread, or now if it already is."""
        with self._lock:
            if not self._done.is_set():
                self._callbacks.append(callback)
                return
        callback()

    def cancel(self) -> None:
        self.cancelled = True

    def _draw(self) -> None:
        try:
            if self.cancelled:
                self.error = "not drawn: nobody waits for it any more"
            else:
                self.image = renderer_choice.camera_renderer().render(self.world, self.view, self.data)
                self.result = self.finish(self.image)
        except Exception:
            self.error = traceback.format_exc()
        finally:
            _give_back(self.world, self.data)
            self.data = None
            self._finished()

    def _finished(self) -> None:
        with self._lock:
            self._done.set()
            callbacks, self._callbacks = self._callbacks, []
        for callback in callbacks:
            callback()


def draw(world, view: render.View, finish: Callable[[np.ndarray], object] = lambda image: None) -> Frame:
    """Copy the world's state now and draw `view` of it on the render thread; the Frame says when."""
    frame = Frame(world, view, finish)
    _submit(frame)
    return frame


def prepare(world, width: int, height: int) -> None:
    """Get the renderer ready to draw `world` at this size (a camera's CAMInit), on the render
    thread: choosing it, OpenGL's context and the world's GPU copy, a spare copy of the state."""
    _submit((world, width, height))


# -- copies of the physics state, kept per world for reuse ---------------------------------------
_spare_lock = threading.Lock()
_spare: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()  # world -> [MjData], at most one per frame in flight


def _copy_state(world) -> mujoco.MjData:
    with _spare_lock:
        spares = _spare.get(world)
        data = spares.pop() if spares else None
    if data is None:
        data = mujoco.MjData(world.model)  # ms for a large world: prepare() makes one ahead
    mujoco.mj_copyData(data, world.model, world.data)
    return data


def _give_back(world, data: mujoco.MjData) -> None:
    with _spare_lock:
        _spare.setdefault(world, []).append(data)


# -- the thread --------------------------------------------------------------------------------------
_jobs: queue.SimpleQueue = queue.SimpleQueue()
_start_lock = threading.Lock()
_thread: threading.Thread | None = None


def _submit(job) -> None:
    global _thread
    with _start_lock:
        if _thread is None or not _thread.is_alive():  # not alive: it ended with the main thread
            _thread = threading.Thread(target=_run, name="eyesim-render")
            _thread.start()
    _jobs.put(job)


def _run() -> None:
    main = threading.main_thread()
    while True:
        try:
            job = _jobs.get(timeout=EXIT_CHECK)
        except queue.Empty:
            if main.is_alive():
                continue
            break
        if isinstance(job, Frame):
            if not main.is_alive():
                job.cancel()  # the process is ending: nobody will see it
            job._draw()
        else:
            _prepare(*job)
    renderer_choice.close_renderer()


def _prepare(world, width: int, height: int) -> None:
    try:
        renderer = renderer_choice.camera_renderer()
        if hasattr(renderer, "prepare"):
            renderer.prepare(world, width, height)
    except Exception:  # the first frame meets the same problem and reports it
        log.debug("preparing the renderer failed:\n%s", traceback.format_exc())
    with _spare_lock:
        if not _spare.get(world):
            _spare.setdefault(world, []).append(mujoco.MjData(world.model))
