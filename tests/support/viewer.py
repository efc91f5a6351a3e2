"""The in-process simulator with its viewer server, and running asyncio code from sync tests."""

from __future__ import annotations

import asyncio
import contextlib
from concurrent.futures import ThreadPoolExecutor

from support.simulator import running_simulation

from eyesim.web.io_thread import IoThread
from eyesim.web.server import ViewerServer


@contextlib.contextmanager
def viewer_simulation(scene, mode: str = "realtime", root=None):
    """Yield (sim, program port, viewer server) with everything running; `root` is the scene
    folder the robot editor opens and saves in (default: the current folder)."""
    with running_simulation(scene, mode) as (sim, port):
        io = IoThread()
        io.start()
        server = ViewerServer(sim, io, "127.0.0.1", 0, run_folder=root, require_token=False)
        server.start()
        try:
            yield sim, port, server
        finally:
            server.stop()
            io.stop()


def run_async(coroutine):
    """Run a coroutine on a thread of its own: pytest may already run an event loop in this
    thread (Playwright's), and asyncio.run refuses to nest."""
    with ThreadPoolExecutor(1) as thread:
        return thread.submit(asyncio.run, coroutine).result()
