"""The worst legal request of every operation (tests/support/worst_requests.py: 16 MiB strings and
images, int32 limits, the 5-megapixel camera) is answered by a live simulator with a browser
watching, and leaves the process's memory within 150 MB of where it started. What each costs the
simulation thread is measured by bench/bench_worst_requests.py, not asserted here."""

from __future__ import annotations

import asyncio
import threading

import aiohttp
from support.client import ProgramClient
from support.memory import rss_mb
from support.viewer import viewer_simulation
from support.worlds import arena_scene, example_robot
from support.worst_requests import worst_hello, worst_requests

from eyesim.protocol import encode_message, generated as g

MEMORY_LIMIT_MB = 150


class WatchingBrowser:
    """A WebSocket that reads (and drops) everything the viewer sends, on a loop of its own."""

    def __init__(self, port: int):
        self.loop = asyncio.new_event_loop()
        self.thread = threading.Thread(target=self.loop.run_forever, daemon=True)
        self.thread.start()
        self.messages = 0
        self.opened = threading.Event()
        self.task = asyncio.run_coroutine_threadsafe(self._watch(port), self.loop)
        assert self.opened.wait(10)

    async def _watch(self, port: int):
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(f"ws://127.0.0.1:{port}/ws", max_msg_size=0) as ws:
                self.ws = ws
                self.opened.set()
                async for _ in ws:
                    self.messages += 1

    def close(self):
        asyncio.run_coroutine_threadsafe(self.ws.close(), self.loop).result(10)
        self.task.result(10)  # the reading loop ends with the connection
        self.loop.call_soon_threadsafe(self.loop.stop)
        self.thread.join(5)


def test_the_worst_request_of_every_operation_is_answered_within_bounded_memory():
    scene = arena_scene(
        [("S4", (500, 500, 0)), (example_robot("Picker"), (1500, 1500, 0))], objects=[("Can", (1000, 1500, 0))]
    )
    with viewer_simulation(scene) as (sim, port, server):
        browser = WatchingBrowser(server.port)
        client = ProgramClient(port, timeout=60)
        try:
            client.call("HELLO", *worst_hello(1, client.token))
            # The camera renderer starts at the first image (OpenGL: libraries and a context, about
            # 150 MB once): part of setting up, not something requests pile up.
            client.call("CAM_INIT", 0)
            client.call("CAM_GET")
            start_mb = rss_mb()
            answered = {}
            for request_id, (name, args) in enumerate(worst_requests(1), start=100):
                op = g.OPS_BY_NAME[name]
                client.sock.sendall(encode_message(op.code, g.KIND_REQUEST, request_id, args))
                if not op.blocking:  # a blocking call (KEYGet, OSWait for 24 days, ...) waits for its time
                    while request_id not in answered:
                        message = client.receive()
                        answered[message.request_id] = message.kind
                    assert answered[request_id] in (g.KIND_REPLY, g.KIND_ERROR)
            assert client.call("PSD_GET", 1)[0] > 0  # still served
            end_mb = rss_mb()
            assert browser.messages > 0
        finally:
            client.close()
            browser.close()
    print(f"RSS {start_mb:.0f} MB -> {end_mb:.0f} MB")
    assert end_mb - start_mb < MEMORY_LIMIT_MB, f"RSS grew from {start_mb:.0f} MB to {end_mb:.0f} MB"
