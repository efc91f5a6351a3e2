"""What other programs notice while one program takes 5-megapixel camera images.

A headless realtime `eyesim run` (no call time) of a room with two S4 robots. Program A, in a
process of its own, calls CAMInit(CAM5MP) once and then CAMGet FRAMES times; program B calls
PSDGet in a loop all along and times every round trip: first alone (its baseline), then while A
starts its camera and takes its first frame (the renderer is chosen and prepared then), and while
A's later frames are taken. Prints B's latencies in each phase, each phase's p99 and p99.9 as a
ratio to B's own baseline in the same run (the machine's load moves the absolute figures), and A's
times; writes bench/results/camera_stall.json.

Run:  python3 bench/bench_camera_stall.py [FRAMES]
Target (reliability issue): B's p99 while A takes frames stays near its baseline."""

from __future__ import annotations

import multiprocessing
import statistics
import sys
import tempfile
import time
from pathlib import Path

from common import BENCH, print_table, start_simulator, stop, write_results

sys.path.insert(0, str(BENCH.parent / "tests"))
from support.client import ProgramClient  # noqa: E402
from support.rooms import square_room, write_scene  # noqa: E402

FRAMES = 40
BASELINE_CALLS = 5000
CAM5MP = 5


def take_images(port: int, frames: int, times, started, finished) -> None:
    """Program A: its CAMInit and CAMGet times, in ms, into `times` (a shared list), then the
    moment (perf_counter, the same clock in every process) its first frame came."""
    client = ProgramClient(port, timeout=120)
    client.hello("1")
    started.set()
    begin = time.perf_counter()
    client.call("CAM_INIT", CAM5MP)
    times.append((time.perf_counter() - begin) * 1000)
    for _ in range(frames):
        begin = time.perf_counter()
        client.call("CAM_GET")
        times.append((time.perf_counter() - begin) * 1000)
        if len(times) == 2:
            first_frame_at = time.perf_counter()
    times.append(first_frame_at)
    finished.set()
    client.close()


def round_trip_ms(client: ProgramClient) -> float:
    begin = time.perf_counter()
    client.call("PSD_GET", 1)
    return (time.perf_counter() - begin) * 1000


def timed_round_trip(client: ProgramClient) -> tuple[float, float]:
    """(when it ended, ms it took)."""
    took = round_trip_ms(client)
    return time.perf_counter(), took


def describe(samples: list[float]) -> dict:
    ordered = sorted(samples)
    return {
        "calls": len(samples),
        "median_ms": statistics.median(samples),
        "p99_ms": quantile(ordered, 0.99),
        "p999_ms": quantile(ordered, 0.999),
        "max_ms": ordered[-1],
    }


def quantile(ordered: list[float], q: float) -> float:
    return ordered[min(len(ordered) - 1, int(len(ordered) * q))]


def main() -> int:
    frames = int(sys.argv[1]) if len(sys.argv) > 1 else FRAMES
    with tempfile.TemporaryDirectory() as folder:
        scene = write_scene(Path(folder), square_room(), ["S4 500 500 0", "S4 1500 1500 180"])
        simulator, port = start_simulator(str(scene), "--headless", "--clock", "realtime", "--call-time", "0")
        try:
            other = ProgramClient(port)
            other.hello("2")
            baseline = [round_trip_ms(other) for _ in range(BASELINE_CALLS)]
            context = multiprocessing.get_context("spawn")
            times, started, finished = context.Manager().list(), context.Event(), context.Event()
            camera = context.Process(target=take_images, args=(port, frames, times, started, finished))
            camera.start()
            started.wait(60)
            during = []
            while not finished.is_set():
                during.append(timed_round_trip(other))
            camera.join(60)
            other.close()
        finally:
            stop(simulator)
    times = list(times)
    first_frame_at, times = times[-1], times[:-1]
    phases = {
        "alone": describe(baseline),
        "CAMInit and the first frame": describe([ms for at, ms in during if at <= first_frame_at]),
        "the later frames": describe([ms for at, ms in during if at > first_frame_at]),
    }
    alone = phases["alone"]
    for r in phases.values():
        r["p99_ratio"], r["p999_ratio"] = r["p99_ms"] / alone["p99_ms"], r["p999_ms"] / alone["p999_ms"]
    rows = [
        (
            name,
            r["calls"],
            f"{r['median_ms']:.3f}",
            f"{r['p99_ms']:.3f}",
            f"{r['p999_ms']:.3f}",
            f"{r['max_ms']:.1f}",
            f"{r['p99_ratio']:.2f}",
            f"{r['p999_ratio']:.2f}",
        )
        for name, r in phases.items()
    ]
    print_table(
        "Program B's PSDGet round trip (ms)",
        rows,
        ("while", "calls", "median", "p99", "p99.9", "max", "p99 / alone", "p99.9 / alone"),
    )
    frames = times[1:]
    print(
        f"\nProgram A: CAMInit(CAM5MP) {times[0]:.1f} ms; CAMGet first {frames[0]:.0f} ms, then median "
        f"{statistics.median(frames[1:]):.0f} ms ({len(frames)} frames)"
    )
    write_results("camera_stall", {"other_program": phases, "cam_init_ms": times[0], "cam_get_ms": frames})
    return 0


if __name__ == "__main__":
    sys.exit(main())
