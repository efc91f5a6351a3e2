"""What the viewer's live history (eyesim/record/live_history.py) costs the process it lives in: the
pause of a full pass of Python's garbage collector over it (measured with gc.callbacks, as a
collection happens on its own in a running simulator), its memory, and what scrubbing back costs
(a frame, the paths, a plotted series).

The history is filled as the soak fills it (bench/soak.py): ROBOTS robots moving for the
history's 120 s of simulation time at 30 snapshots per second, each reading a PSD PSD_RATE times
per second.

Run:  python3 bench/bench_live_history.py [--robots 50] [--psd-rate 100]"""

from __future__ import annotations

import argparse
import asyncio
import gc
import statistics
import time
import tracemalloc

from common import print_table, write_results

from eyesim.record.live_history import HISTORY_SECONDS, LiveHistory
from eyesim.record.timeline import FrameCursor, answer

SNAPSHOTS_PER_SECOND = 30


def fill(history: LiveHistory, robots: int, psd_rate: int) -> None:
    for step in range(HISTORY_SECONDS * SNAPSHOTS_PER_SECOND):
        t = step / SNAPSHOTS_PER_SECOND
        time_us = round(t * 1e6)
        history.add_snapshot(
            {
                "type": "snapshot",
                "time": t,
                "objects": [],
                "bodies": [],
                "robots": [
                    {"id": r, "pos": [0.1 * r + t / 100, 0.5, 0.05], "quat": [1.0, 0.0, 0.0, t / 1000], "battery": 8.1}
                    for r in range(1, robots + 1)
                ],
            },
            [
                {
                    "robot": r,
                    "odometry": {"x": t / 100, "y": 0.5, "phi": 0.01},
                    "speed": {"v": 0.01, "w": 0.0},
                    "encoders": {"1": step, "2": step},
                    "battery": 8.1,
                }
                for r in range(1, robots + 1)
            ],
        )
        for r in range(1, robots + 1):
            for k in range(psd_rate // SNAPSHOTS_PER_SECOND):
                history.add_psd(r, time_us + k, {"robot": r, "psd": 1, "distance_mm": 500 + k})


def full_collections(count: int) -> list[float]:
    """Seconds each of `count` full collections took, timed by gc.callbacks."""
    pauses, started = [], []

    def timer(phase, info):
        if info["generation"] == 2:
            if phase == "start":
                started.append(time.perf_counter())
            else:
                pauses.append(time.perf_counter() - started.pop())

    gc.callbacks.append(timer)
    try:
        for _ in range(count):
            gc.collect()
    finally:
        gc.callbacks.remove(timer)
    return pauses


async def scrub(history: LiveHistory) -> tuple[float, float, float]:
    """Seconds for a frame at the history's middle, the paths, one robot's odometry series."""
    start = time.perf_counter()
    await answer(history, FrameCursor(), {"type": "seek", "time": (history.start_us + history.end_us) / 2e6})
    frame = time.perf_counter()
    await answer(history, FrameCursor(), {"type": "paths"})
    paths = time.perf_counter()
    await answer(history, FrameCursor(), {"type": "series", "ids": ["robot/1/odometry.x", "robot/1/psd.1"]})
    return frame - start, paths - frame, time.perf_counter() - paths


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robots", type=int, default=50)
    parser.add_argument("--psd-rate", type=int, default=100, help="PSD readings per robot and second")
    arguments = parser.parse_args()
    empty = statistics.median(full_collections(5))
    tracemalloc.start()
    history = LiveHistory(list(range(1, arguments.robots + 1)))
    fill(history, arguments.robots, arguments.psd_rate)
    size = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    full = statistics.median(full_collections(5))
    frame, paths, series = asyncio.run(scrub(history))
    rows = [
        ("full GC pass, no history", f"{empty * 1000:.1f} ms"),
        ("full GC pass, with the history", f"{full * 1000:.1f} ms"),
        ("objects the GC tracks", f"{len(gc.get_objects())}"),
        ("history memory", f"{size / 1e6:.0f} MB"),
        ("frame at the middle", f"{frame * 1000:.1f} ms"),
        ("paths", f"{paths * 1000:.1f} ms"),
        ("two series", f"{series * 1000:.1f} ms"),
    ]
    print_table(
        f"Live history of {arguments.robots} robots, {HISTORY_SECONDS} s, {arguments.psd_rate} PSD readings/s each",
        rows,
        ("what", "cost"),
    )
    write_results(
        "live_history",
        {
            "robots": arguments.robots,
            "psd_rate": arguments.psd_rate,
            "gc_pass_ms": {"empty": empty * 1000, "full": full * 1000},
            "history_bytes": size,
            "frame_ms": frame * 1000,
            "paths_ms": paths * 1000,
            "series_ms": series * 1000,
        },
    )


if __name__ == "__main__":
    main()
