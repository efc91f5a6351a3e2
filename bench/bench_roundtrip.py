"""Round trip of PSDGet from C programs (realtime mode) beside raw TCP echo round trips: one
program alone, and ten programs calling at once (each on its own robot; all their samples) beside
ten clients calling a one-threaded C echo server at once.

Baselines measured in the same run: a C echo server (the kernel's floor) and an asyncio echo
server in Python (the floor of the runtime our server is written in). Prints a table, writes
bench/results/roundtrip.json."""

from __future__ import annotations

import asyncio
import os
import subprocess
import sys
import threading
from importlib.resources import files
from pathlib import Path

from common import BENCH, build_c, print_table, start_simulator, stop, summary, write_results

CALLS = 1000
BUILD = BENCH / "results" / "build"


def eyesim_data(relative: str) -> str:
    return str(files("eyesim") / "data" / relative)


def samples(output: str) -> list[float]:
    return [float(line) for line in output.split()]


def c_echo(client, clients: int = 1) -> list[float]:
    """Round trips against a one-threaded C server (poll) with `clients` clients calling at once."""
    server_binary = build_c(BENCH / "programs" / "echo_server.c", BUILD / "echo_server")
    server = subprocess.Popen([str(server_binary), str(clients)], stdout=subprocess.PIPE, text=True)
    port = server.stdout.readline().strip()
    runs = [
        subprocess.Popen([str(client), port, str(CALLS)], stdout=subprocess.PIPE, text=True) for _ in range(clients)
    ]
    outputs = [run.communicate()[0] for run in runs]
    server.wait(timeout=10)
    return [sample for output in outputs for sample in samples(output)]


def python_echo(client) -> list[float]:
    loop = asyncio.new_event_loop()
    threading.Thread(target=loop.run_forever, daemon=True).start()

    class Echo(asyncio.Protocol):
        def connection_made(self, transport):
            self.transport = transport

        def data_received(self, data):
            self.transport.write(data)

    server = asyncio.run_coroutine_threadsafe(loop.create_server(Echo, "127.0.0.1", 0), loop).result()
    port = server.sockets[0].getsockname()[1]
    result = subprocess.run([str(client), str(port), str(CALLS)], capture_output=True, text=True, check=True)
    loop.call_soon_threadsafe(loop.stop)
    return samples(result.stdout)


def psd_get(programs: int = 1) -> list[float]:
    program = build_c(BENCH / "programs" / "psd_roundtrip.c", BUILD / "psd_roundtrip")
    scene = BUILD / f"roundtrip_{programs}.sim"  # the bundled arena with one S4 per program
    arena = Path(eyesim_data("scenes/arena.wld"))
    scene.write_text(f"world {arena}\n" + "".join(f"S4 {300 + 150 * i} 500 90\n" for i in range(programs)))
    # --call-time 0: replies as soon as they are ready (the default holds each one for the per-call time,
    # bench_call_time.py); this measures the round trip itself.
    simulator, port = start_simulator(str(scene), "--headless", "--clock", "realtime", "--call-time", "0")
    try:
        clients = [
            subprocess.Popen(
                [str(program), str(CALLS)],
                stdout=subprocess.PIPE,
                text=True,
                env=dict(os.environ, EYESIM_PORT=str(port), EYESIM_ROBOT=str(robot)),
            )
            for robot in range(1, programs + 1)
        ]
        outputs = [client.communicate()[0] for client in clients]
    finally:
        stop(simulator)
    return [sample for output in outputs for sample in samples(output)]


def main() -> int:
    client = build_c(BENCH / "programs" / "echo_client.c", BUILD / "echo_client")
    results = {
        "c_echo": summary(c_echo(client)),
        "python_echo": summary(python_echo(client)),
        "psd_get": summary(psd_get()),
        "c_echo_10_clients": summary(c_echo(client, 10)),
        "psd_get_10_programs": summary(psd_get(10)),
    }
    # each against the C echo with as many clients calling at once
    bases = {name: results["c_echo_10_clients" if "10" in name else "c_echo"]["median_ms"] for name in results}
    rows = [
        (
            name,
            f"{r['mean_ms']:.3f}",
            f"{r['median_ms']:.3f}",
            f"{r['p99_ms']:.3f}",
            f"{r['median_ms'] / bases[name]:.1f}x",
        )
        for name, r in results.items()
    ]
    print_table(f"Round trip, {CALLS} calls (ms)", rows, ("what", "mean", "median", "p99", "median vs C echo"))
    print(
        "targets: PSDGet median <= 0.10 ms and <= 3x the C echo, p99 <= 0.5 ms, alone and with 10 programs "
        "(EyeSim V2 published: mean 4.587, median 4.642)"
    )
    print(f"wrote {write_results('roundtrip', results)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
