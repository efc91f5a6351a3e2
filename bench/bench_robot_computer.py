"""Cost of the robot-computer functions (LCD, keys, serial, I/O) from a C program in realtime mode,
as ratios to the simplest round trip (OSGetCount) measured in the same run, and how punctual a
10 ms timer is in simulation time; then, in deterministic mode, how fast a 1 ms timer runs
compared with as many OSWait(1) calls. Prints tables, writes bench/results/robot_computer.json."""

from __future__ import annotations

import os
import statistics
import subprocess
from collections import defaultdict

from common import BENCH, build_c, print_table, start_simulator, stop, summary, write_results

CALLS = 300
BUILD = BENCH / "results" / "build"


def main() -> None:
    program = build_c(BENCH / "programs" / "robot_computer_calls.c", BUILD / "robot_computer_calls")
    # --call-time 0 here and below: the round trips themselves, not the per-call time (bench_call_time.py).
    simulator, port = start_simulator(
        "--headless", "--clock", "realtime", "--call-time", "0", "--serial-loopback", "1:0"
    )
    try:
        env = dict(os.environ, EYESIM_PORT=str(port))
        result = subprocess.run([str(program), str(CALLS)], capture_output=True, text=True, check=True, env=env)
    finally:
        stop(simulator)
    samples: dict[str, list[float]] = defaultdict(list)
    for line in result.stdout.splitlines():
        name, value = line.split()
        samples[name].append(float(value))
    lateness = samples.pop("timer_lateness_ms")
    stats = {name: summary(values) for name, values in samples.items()}
    baseline = stats["OSGetCount"]["median_ms"]
    rows = [
        (name, s["n"], f"{s['median_ms']:.3f}", f"{s['p99_ms']:.3f}", f"{s['median_ms'] / baseline:.1f}")
        for name, s in stats.items()
    ]
    print_table(
        "Robot-computer calls from C, realtime mode (wall-clock ms per call)",
        rows,
        ("call", "n", "median ms", "p99 ms", "x OSGetCount"),
    )
    timer = {
        "callbacks": len(lateness),
        "mean_late_ms": statistics.fmean(lateness),
        "max_late_ms": max(lateness),
        "min_late_ms": min(lateness),
    }
    print(
        f"\n10 ms timer, {timer['callbacks']} callbacks: lateness in simulation time "
        f"mean {timer['mean_late_ms']:.2f} ms, min {timer['min_late_ms']:.0f} ms, max {timer['max_late_ms']:.0f} ms"
    )
    simulator, port = start_simulator("--headless", "--clock", "deterministic", "--call-time", "0")
    try:
        env = dict(os.environ, EYESIM_PORT=str(port))
        result = subprocess.run([str(program), "rate"], capture_output=True, text=True, check=True, env=env)
    finally:
        stop(simulator)
    rate = {name: float(value) for name, value in (line.split() for line in result.stdout.splitlines())}
    print(
        f"\nDeterministic mode, 2 s of simulation time: a 1 ms timer ({rate['callbacks']:.0f} callbacks) "
        f"{rate['timer_1ms_2000_callbacks_s']:.3f} s wall, 2000 x OSWait(1) {rate['oswait_1ms_2000_calls_s']:.3f} s "
        f"wall (x{rate['timer_1ms_2000_callbacks_s'] / rate['oswait_1ms_2000_calls_s']:.2f})"
    )
    path = write_results(
        "robot_computer", {"calls": stats, "baseline": "OSGetCount", "timer_10ms": timer, "deterministic_rate": rate}
    )
    print(f"\nwritten to {path.relative_to(BENCH.parent)}")


if __name__ == "__main__":
    main()
