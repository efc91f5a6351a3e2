"""What the worst legal request of each operation costs the simulation thread.

Each request of tests/support/worst_requests.py (largest strings, images and values the protocol
allows) is taken exactly as the simulation thread takes it from a socket: the frame reassembled
and decoded, its values checked against protocol.json's ranges, the handler run and the reply
encoded. Sockets are left out (their cost does not depend on the operation, bench_roundtrip.py).
The simulation does not run its loop, so this thread is the simulation thread; the clock is
deterministic so that replies are sent, not held for the call time. A camera image is drawn on the
render thread (physics/render_worker.py): its time there is shown beside, waited for before the
next request so that it does not slow that one down.

Run:  python3 bench/bench_worst_requests.py [--repeat 4]
Target (reliability issue): every worst request costs < 5 ms of simulation-thread time."""

from __future__ import annotations

import argparse
import statistics
import sys
import time

from common import BENCH, print_table, write_results

sys.path.insert(0, str(BENCH.parent / "tests"))
from support.worlds import arena_scene, example_robot  # noqa: E402
from support.worst_requests import worst_hello, worst_requests  # noqa: E402

from eyesim.core.clock import Clock  # noqa: E402
from eyesim.core.engine import Simulation  # noqa: E402
from eyesim.net.session import Deferred, Request, Session  # noqa: E402
from eyesim.protocol import FrameDecoder, decode_payload, encode_message, generated as g  # noqa: E402

TARGET_MS = 5.0


class Collector:
    """A connection that keeps the size of what the simulation sends."""

    def __init__(self):
        self.sent = []

    def send(self, data: bytes) -> None:
        self.sent.append(len(data))

    def close(self) -> None:
        pass

    def resume(self) -> None:
        pass


def take(sim: Simulation, session: Session, name: str, args: tuple, request_id: int) -> tuple[float, float]:
    """Seconds the simulation thread spends on one request, from its bytes to its reply (or to the
    hand-over of a Deferred one), and seconds until a Deferred reply was made on its thread."""
    op = g.OPS_BY_NAME[name]
    frame = encode_message(op.code, g.KIND_REQUEST, request_id, args)
    start = time.perf_counter()
    (message,) = FrameDecoder().feed(frame)
    request = Request(
        session,
        op,
        message.request_id,
        decode_payload(op.request, message.payload, op.lengths),
        max(sim.time_us, session.local_time_us),
    )
    sim.requests.execute(request)
    spent = time.perf_counter() - start
    deferred = [p for _, p in session.pending if isinstance(p, Deferred)]
    for pending in deferred:
        pending.work.wait()
    made = time.perf_counter() - start if deferred else 0.0
    if deferred:  # its reply: sent when its cost in simulation time has passed
        start = time.perf_counter()
        sim.requests.wake_session(session, max(p.wake_us for p in deferred))
        spent += time.perf_counter() - start
    return spent, made


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=4, help="times each request is taken")
    arguments = parser.parse_args()
    scene = arena_scene(
        [("S4", (500, 500, 0)), (example_robot("Picker"), (1500, 1500, 0))], objects=[("Can", (1000, 1500, 0))]
    )
    sim = Simulation(scene, Clock("deterministic"))
    session = Session(connection=Collector(), peer="bench")
    sim.requests.connected(session)
    times = {("HELLO", "16 MiB program name"): [take(sim, session, "HELLO", worst_hello(1), 1)[0]]}
    elsewhere = {}  # ms on the render thread, per request
    request_id = 2
    for name, args in worst_requests(1):
        label = ", ".join(_short(a) for a in args)
        while (name, label) in times:  # a second worst request of the same operation
            label += " "
        times[(name, label)] = []
        for _ in range(arguments.repeat):
            request_id += 1
            spent, made = take(sim, session, name, args, request_id)
            times[(name, label)].append(spent)
            if made:
                elsewhere.setdefault((name, label), []).append(made)
        sim.step()  # time goes on between requests, as it would
    # The first of a kind may pay for starting something once; the target is for the others, the
    # typical cost of the request itself. Firsts over it are listed below the table.
    rows = []
    for (name, label), seconds in times.items():
        then = statistics.median(seconds[1:] or seconds) * 1000
        made = elsewhere.get((name, label))
        rows.append(
            (
                name,
                label,
                f"{seconds[0] * 1000:.3f}",
                f"{then:.3f}",
                f"{made[0] * 1000:.0f} / {statistics.median(made[1:] or made) * 1000:.0f}" if made else "",
                "ok" if then < TARGET_MS else "OVER",
            )
        )
    print_table(
        f"Worst request of each operation, simulation-thread time in ms (target < {TARGET_MS:g} ms): "
        f"the first, then the median of {arguments.repeat - 1} more; a camera image's time on the "
        f"render thread (first / then)",
        rows,
        ("op", "request", "first", "then", "render thread", "target"),
    )
    over = [row for row in rows if row[5] == "OVER"]
    print(
        f"\n{len(rows) - len(over)} of {len(rows)} within {TARGET_MS:g} ms"
        + (": over: " + ", ".join(f"{r[0]} {r[3]} ms" for r in over) if over else "")
    )
    first_over = [row for row in rows if float(row[2]) >= TARGET_MS]
    print("first of a kind over it: " + (", ".join(f"{r[0]} {r[2]} ms" for r in first_over) or "none"))
    write_results(
        "worst_requests",
        {
            "target_ms": TARGET_MS,
            "rows": [
                {
                    "op": name,
                    "request": label,
                    "ms": [s * 1000 for s in seconds],
                    "render_thread_ms": [s * 1000 for s in elsewhere.get((name, label), [])],
                }
                for (name, label), seconds in times.items()
            ],
        },
    )


def _short(value) -> str:
    if isinstance(value, bytes) and value[:2] == b"\xff\xff":
        return f"{len(value) / (1 << 20):.0f} MiB of MP3 frames"
    if isinstance(value, (str, bytes)):
        return f"{len(value) / (1 << 20):.0f} MiB" if len(value) > 1 << 20 else f"{len(value)} B"
    return str(value)


if __name__ == "__main__":
    main()
