"""Real time under load: N C programs poll PSDGet/VWGetPosition as fast as they can in realtime
mode, beside one program that pipelines LIDAR scans and never reads them.

For 1, 5, 20, 50 and 100 programs: the simulation's real-time factor while they poll (simulation
time that passed / wall time, as the programs saw it), total calls per second, fairness (most /
fewest calls of one program) and latency (median of the programs' medians, worst p99, worst max).
Run with the call time 0 (answered as soon as served: the server's own capacity) and with the
default call time (4 ms: each program then makes at most 250 calls per simulated second).

Run:  python3 bench/bench_load.py [--programs 1 5 20 50 100] [--seconds 5] [--call-time 0 4]
Targets (performance issue): real time >= 0.95x with 20 and 100 programs, max/min calls <= 2,
>= 20,000 calls/s in total, p99 <= 5 ms with 20 programs; the non-reader affects nobody."""

from __future__ import annotations

import argparse
import math
import os
import socket
import subprocess
import sys

from common import BENCH, build_c, print_table, start_simulator, stop, write_results

sys.path.insert(0, str(BENCH.parent / "tests"))
from support.client import ProgramClient  # noqa: E402

from eyesim.protocol import encode_message, generated as g  # noqa: E402

BUILD = BENCH / "results" / "build"
NICE = os.environ.get("NICE", "").split()


def scene_file(programs: int) -> str:
    """A square arena with one S4 per program plus one for the program that never reads."""
    robots = programs + 1
    side = math.ceil(math.sqrt(robots))
    size = 400 * side + 400
    path = BUILD / f"load_{programs}.sim"
    world = BUILD / f"load_{programs}.wld"
    world.write_text(
        f"floor {size} {size}\n0 0 {size} 0\n{size} 0 {size} {size}\n{size} {size} 0 {size}\n0 {size} 0 0\n"
    )
    placements = "".join(f"S4 {400 + 400 * (i % side)} {400 + 400 * (i // side)} 90\n" for i in range(robots))
    path.write_text(f"world {world.name}\n" + placements)
    return str(path)


def non_reader(port: int, robot: int) -> socket.socket:
    client = ProgramClient(port)
    client.hello(str(robot))
    client.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    frames = b"".join(encode_message(g.OP_LIDAR_GET, g.KIND_REQUEST, i + 2, ()) for i in range(20000))
    client.sock.setblocking(False)
    try:
        client.sock.send(frames)  # as much as the kernel takes; the rest never
    except BlockingIOError:
        pass
    return client.sock


def cpu_seconds(pid: int) -> float:
    """User + system CPU time of a process so far (Linux /proc)."""
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def run(programs: int, seconds: float, call_time: float) -> dict:
    program = build_c(BENCH / "programs" / "poll_load.c", BUILD / "poll_load")
    simulator, port = start_simulator(
        scene_file(programs), "--headless", "--clock", "realtime", "--call-time", f"{call_time:g}"
    )
    try:
        stuck = non_reader(port, programs + 1)
        clients = [
            subprocess.Popen(
                NICE + [str(program), str(seconds)],
                stdout=subprocess.PIPE,
                text=True,
                env=dict(os.environ, EYESIM_PORT=str(port), EYESIM_ROBOT=str(robot)),
            )
            for robot in range(1, programs + 1)
        ]
        cpu_before = cpu_seconds(simulator.pid)
        rows = [list(map(float, client.communicate()[0].split())) for client in clients]
        simulator_cpu = (cpu_seconds(simulator.pid) - cpu_before) / seconds
        stuck.close()
    finally:
        stop(simulator)
    calls = [r[0] for r in rows]
    return {
        "programs": programs,
        "call_time_ms": call_time,
        "real_time": min(r[4] for r in rows) / 1000 / seconds,
        "calls_per_s": sum(calls) / seconds,
        "fairness": max(calls) / max(1, min(calls)),
        "p50_ms": sorted(r[1] for r in rows)[len(rows) // 2] / 1000,
        "p99_ms": max(r[2] for r in rows) / 1000,
        "max_ms": max(r[3] for r in rows) / 1000,
        "simulator_cpu": simulator_cpu,
    }


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--programs", type=int, nargs="+", default=[1, 5, 20, 50, 100])
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--call-time", type=float, nargs="+", default=[0.0, 4.0])
    args = parser.parse_args()
    results = [run(n, args.seconds, t) for t in args.call_time for n in args.programs]
    rows = [
        (
            r["call_time_ms"],
            r["programs"],
            f"{r['real_time']:.2f}x",
            f"{r['calls_per_s']:.0f}",
            f"{r['fairness']:.2f}",
            f"{r['p50_ms']:.3f}",
            f"{r['p99_ms']:.2f}",
            f"{r['max_ms']:.1f}",
            f"{r['simulator_cpu']:.0%}",
        )
        for r in results
    ]
    print_table(
        f"Polling programs in realtime mode, {args.seconds:g} s each, plus one that never reads",
        rows,
        (
            "call time ms",
            "programs",
            "real time",
            "calls/s",
            "max/min calls",
            "p50 ms",
            "p99 ms",
            "max ms",
            "simulator CPU",
        ),
    )
    print("targets: real time >= 0.95x (20, 100 programs), max/min <= 2, >= 20000 calls/s, p99 <= 5 ms (20)")
    print(f"wrote {write_results('load', {'runs': results})}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
