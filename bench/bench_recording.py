"""Recording size and cost: a minute of three robots that drive, take a QVGA camera image ten times a
second, show it on their LCD and read their PSDs, recorded to MCAP at the default pose rate (100 Hz)
and at 30 Hz, beside the same run unrecorded (the baseline for the time it costs).

Headless and deterministic, so every run simulates the same minute. Prints MB per simulated minute,
the bytes per channel (before compression) and the wall time against the baseline; writes
bench/results/recording.json."""

from __future__ import annotations

import subprocess
import sys
import time
from collections import Counter

from common import BENCH, build_c, eyesim, print_table, write_results

sys.path.insert(0, str(BENCH.parent))

from mcap.reader import make_reader  # noqa: E402

from eyesim.paths import DATA_DIR  # noqa: E402

SECONDS = 60
BUILD = BENCH / "results" / "build"
SCENE = f"""world {DATA_DIR / "scenes" / "arena.wld"}
settings VIS TRACE
S4 400 400 0
S4 1600 400 90
S4 400 1600 -45
"""


def run(*record: str) -> float:
    """Wall seconds of one headless run of SECONDS simulated seconds."""
    programs = [arg for robot in (1, 2, 3) for arg in ("--program", f"{robot}={BUILD / 'camera_patrol'}")]
    start = time.perf_counter()
    subprocess.run(
        eyesim(
            "run", str(BUILD / "patrol.sim"), "--headless", "--port", "0", "--until", str(SECONDS), *programs, *record
        ),
        check=True,
        cwd=BUILD,
        stdout=subprocess.DEVNULL,
    )
    return time.perf_counter() - start


def channel_bytes(path) -> Counter:
    """Message bytes per channel kind (robot channels summed over the robots)."""
    sizes: Counter = Counter()
    with open(path, "rb") as file:
        for _, channel, message in make_reader(file).iter_messages():
            parts = channel.topic.split("/")
            sizes["/robot/*/" + parts[3] if len(parts) == 4 else channel.topic] += len(message.data)
    return sizes


def main() -> None:
    build_c(BENCH / "programs" / "camera_patrol.c", BUILD / "camera_patrol")
    (BUILD / "patrol.sim").write_text(SCENE)
    baseline = run()
    results = {"simulated_seconds": SECONDS, "robots": 3, "baseline_wall_s": round(baseline, 2), "recordings": {}}
    rows = [("no recording", "-", "-", f"{baseline:.1f}", "1.00")]
    for rate in (100, 30):
        path = BUILD / f"patrol-{rate}.mcap"
        wall = run("--record", str(path), "--record-rate", str(rate))
        megabytes = path.stat().st_size / 1e6
        per_minute = megabytes * 60 / SECONDS
        sizes = channel_bytes(path)
        results["recordings"][f"{rate}Hz"] = {
            "file_mb": round(megabytes, 2),
            "mb_per_minute": round(per_minute, 2),
            "wall_s": round(wall, 2),
            "wall_ratio": round(wall / baseline, 2),
            "message_mb_by_channel": {k: round(v / 1e6, 2) for k, v in sizes.most_common()},
        }
        rows.append(
            (f"--record-rate {rate}", f"{megabytes:.1f}", f"{per_minute:.1f}", f"{wall:.1f}", f"{wall / baseline:.2f}")
        )
    print_table(
        f"Recording {SECONDS} s of 3 robots with cameras (10 QVGA images/s each, LCD showing them)",
        rows,
        ("run", "file MB", "MB/min", "wall s", "x baseline"),
    )
    for rate, result in results["recordings"].items():
        print(
            f"\n{rate}: message MB by channel (before zstd):",
            ", ".join(f"{k} {v}" for k, v in result["message_mb_by_channel"].items()),
        )
    print(f"\nwrote {write_results('recording', results)}")


if __name__ == "__main__":
    main()
