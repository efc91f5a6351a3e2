"""Awaiting work done on the simulation thread from the viewer's routes (I/O thread)."""

from __future__ import annotations

import asyncio
import concurrent.futures


def on_simulation(sim, action) -> asyncio.Future:
    """Run `action(sim)` on the simulation thread; its result (or exception) as an awaitable."""
    future: concurrent.futures.Future = concurrent.futures.Future()

    def run(simulation):
        if not future.set_running_or_notify_cancel():
            return  # the route gave up waiting
        try:
            future.set_result(action(simulation))
        except Exception as error:  # handed to the route that asked, which reports it
            future.set_exception(error)

    sim.on_loop(run)
    return asyncio.wrap_future(future)
