"""What one call costs the simulation thread, without the scheduling of another process: a realtime
simulation (arena, one S4) and one client socket on the same thread, the client sending a request
and the simulation loop turning until the reply is there. Times are CPU time of that one thread
(time.thread_time), so they hold still on a busy machine: the simulator's Python, its socket calls
and the client's. The baseline is the same socket calls alone on a bare socket pair (send,
select, recv, send, recv), measured in the same run.

Run:  PYTHONPATH=src python3 bench/bench_call_path.py [--calls 10000]
Compare versions by running it with PYTHONPATH pointing at each one's src, alternately.
"""

from __future__ import annotations

import argparse
import os
import selectors
import socket
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
from common import print_table, write_results  # noqa: E402
from support.scenes import arena  # noqa: E402

from eyesim.core.engine import Simulation  # noqa: E402
from eyesim.net.program_server import ProgramServer  # noqa: E402
from eyesim.protocol import FrameDecoder, encode_message, generated as g  # noqa: E402

REPEATS = 3  # best of


def best_cpu_per_call(call, calls: int) -> float:
    best = float("inf")
    for _ in range(REPEATS):
        start = time.thread_time()
        for _ in range(calls):
            call()
        best = min(best, (time.thread_time() - start) / calls)
    return best


def bare_sockets(calls: int) -> float:
    listener = socket.create_server(("127.0.0.1", 0))
    client = socket.create_connection(listener.getsockname())
    server, _ = listener.accept()
    for end in (client, server):
        end.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    server.setblocking(False)
    selector = selectors.DefaultSelector()
    selector.register(server, selectors.EVENT_READ)
    request, reply = bytes(12), bytes(20)

    def round_trip():
        client.send(request)
        selector.select(0)
        server.recv(65536)
        server.send(reply)
        client.recv(65536)

    try:
        return best_cpu_per_call(round_trip, calls)
    finally:
        for end in (client, server, listener):
            end.close()
        selector.close()


class OneThreadClient:
    """A program's socket served by the simulation loop on the caller's own thread."""

    def __init__(self):
        self.sim = Simulation(arena())
        self.sim.call_time_us = 0  # the reply leaves at once: the call path, not the call time
        self.server = ProgramServer(self.sim, "127.0.0.1", 0)
        self.server.start()
        self.sim.clock.anchor(0)
        self.sim.handle_queued()  # the listener joins the selector
        self.sock = socket.create_connection(("127.0.0.1", self.server.port))
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.sock.setblocking(False)
        self.decoder = FrameDecoder()
        self.call(
            encode_message(g.OP_HELLO, g.KIND_REQUEST, 1, (g.VERSION, "1", "bench", os.getpid(), self.server.token))
        )

    def call(self, frame: bytes) -> None:
        self.sock.send(frame)
        while True:
            self.sim.timing.round()
            try:
                data = self.sock.recv(65536)
            except BlockingIOError:
                continue
            (reply,) = self.decoder.feed(data)
            if reply.kind != g.KIND_REPLY:
                raise RuntimeError(f"{g.OPS[reply.op].name} was refused")
            return

    def close(self) -> None:
        self.sock.close()
        self.server.stop()
        self.sim.close()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=10000)
    args = parser.parse_args()
    results = {"bare_sockets_us": bare_sockets(args.calls) * 1e6}
    client = OneThreadClient()
    try:
        for name, op, values in (
            ("OSGetCount", g.OP_OS_GET_COUNT, ()),
            ("PSDGet", g.OP_PSD_GET, (1,)),
            ("VWGetPosition", g.OP_VW_GET_POSITION, ()),
        ):
            frame = encode_message(op, g.KIND_REQUEST, 2, values)
            results[f"{name}_us"] = best_cpu_per_call(lambda: client.call(frame), args.calls) * 1e6
    finally:
        client.close()
    base = results["bare_sockets_us"]
    rows = [("socket calls alone (baseline)", f"{base:.1f}", "")]
    rows += [(name[:-3], f"{us:.1f}", f"{us - base:.1f}") for name, us in results.items() if name != "bare_sockets_us"]
    print_table(
        f"CPU per call, one thread, best of {REPEATS} x {args.calls} (us)",
        rows,
        ("call", "CPU per call", "beyond the socket calls"),
    )
    print(f"wrote {write_results('call_path', results)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
