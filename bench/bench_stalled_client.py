"""A client holding back half a frame must not delay others.

One client sends a valid frame header and holds the body back for 2.5 s; meanwhile a second
client connects, handshakes and completes a PSDGet. Measures the time from the second client's
connect to its PSDGet reply, 10 trials, beside the same measurement with no staller (baseline).
Writes bench/results/stalled_client.json."""

from __future__ import annotations

import socket
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from common import print_table, start_simulator, stop, summary, write_results  # noqa: E402
from support.client import ProgramClient  # noqa: E402
from support.simulator import token_for  # noqa: E402

from eyesim.protocol import encode_message, generated as g  # noqa: E402

TRIALS = 10
HOLD = 2.5


def second_client_ready(port: int) -> float:
    start = time.perf_counter()
    client = ProgramClient(port)
    client.hello()
    client.call("PSD_GET", 1)
    elapsed = time.perf_counter() - start
    client.close()
    return elapsed * 1e6


def trial(port: int, stall: bool) -> float:
    staller = None
    if stall:
        staller = socket.create_connection(("127.0.0.1", port))
        frame = encode_message(g.OP_HELLO, g.KIND_REQUEST, 1, (g.VERSION, "", "staller", 0, token_for(port)))
        staller.sendall(frame[:12])  # length + header + part of the body
        time.sleep(0.05)
    elapsed = second_client_ready(port)
    if staller is not None:
        time.sleep(max(0.0, HOLD - elapsed / 1e6))
        staller.close()
    return elapsed


def main() -> int:
    simulator, port = start_simulator("--headless", "--clock", "realtime", "--call-time", "0")  # round trips only
    try:
        baseline = [trial(port, stall=False) for _ in range(TRIALS)]
        stalled = [trial(port, stall=True) for _ in range(TRIALS)]
    finally:
        stop(simulator)
    results = {"no_staller": summary(baseline), "with_staller": summary(stalled)}
    rows = [(name, f"{r['mean_ms']:.3f}", f"{r['median_ms']:.3f}", f"{r['max_ms']:.3f}") for name, r in results.items()]
    print_table(
        f"Second client: connect + handshake + PSDGet, {TRIALS} trials (ms)", rows, ("what", "mean", "median", "max")
    )
    print("target: served in <= 5 ms with a staller (EyeSim V2 published: 99.38 ms; V1: 2453 ms)")
    print(f"wrote {write_results('stalled_client', results)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
