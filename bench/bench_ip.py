"""Image processing in libeyesim and the cost of the Python `eye` layer, as ratios to baselines
measured in the same run.

1. Each IP function in C on a QVGA and a VGA image, against copying a colour image of that size;
   ip.c compiled at -O2 as the installed (Release) library is; the development build is not optimised.
2. The same functions called through `eye` (new output buffer, argument checks) against calling
   the C function through plain ctypes with ready buffers.
3. A simulator round trip (OSGetCount) from Python through `eye` against the same from C.

Prints tables, writes bench/results/ip.json."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

from common import BENCH, build_c, print_table, start_simulator, stop, summary, write_results

BUILD = BENCH / "results" / "build"
RESOLUTIONS = {"QVGA": 1, "VGA": 2}
CALLS = 1000


def build_speed_program() -> Path:
    """bench/programs/ip_speed.c with robios/src/ip.c, optimised."""
    robios = BENCH.parent / "robios"
    output = BUILD / "ip_speed"
    BUILD.mkdir(parents=True, exist_ok=True)
    subprocess.run(
        [
            "cc",
            "-O2",
            "-std=c11",
            "-D_GNU_SOURCE",
            f"-I{robios / 'include'}",
            f"-I{robios / 'src'}",
            str(BENCH / "programs" / "ip_speed.c"),
            str(robios / "src" / "ip.c"),
            "-o",
            str(output),
            "-lpthread",
        ],
        check=True,
    )
    return output


def c_speeds(program, resolution: int) -> dict[str, float]:
    out = subprocess.run([str(program), str(resolution), "50"], capture_output=True, text=True, check=True).stdout
    return {name: float(us) for name, us in (line.split() for line in out.splitlines())}


def best_of(repeats: int, call) -> float:
    """Microseconds per call, best of 5 runs of `repeats` calls."""
    best = float("inf")
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(repeats):
            call()
        best = min(best, (time.perf_counter() - start) / repeats * 1e6)
    return best


def python_layer() -> dict[str, dict[str, float]]:
    import ctypes

    import eye

    eye.IPSetSize(eye.QVGA)
    gray = (ctypes.c_ubyte * eye.QVGA_PIXELS)()
    colour = (ctypes.c_ubyte * eye.QVGA_SIZE)()
    out = (ctypes.c_ubyte * eye.QVGA_SIZE)()
    raw = eye.lib
    calls = {
        "IPLaplace": (lambda: eye.IPLaplace(gray), lambda: raw.IPLaplace(gray, out)),
        "IPCol2Gray": (lambda: eye.IPCol2Gray(colour), lambda: raw.IPCol2Gray(colour, out)),
        "IPPRGB2Hue": (lambda: eye.IPPRGB2Hue(10, 200, 30), lambda: raw.IPPRGB2Hue(10, 200, 30)),
    }
    return {
        name: {"eye_us": best_of(200, wrapped), "ctypes_us": best_of(200, plain)}
        for name, (wrapped, plain) in calls.items()
    }


PYTHON_ROUNDTRIP = textwrap.dedent("""
    import sys, time
    from eye import OSGetCount
    OSGetCount()
    for _ in range(50):
        OSGetCount()
    for _ in range(int(sys.argv[1])):
        start = time.perf_counter()
        OSGetCount()
        print(f"{(time.perf_counter() - start) * 1e6:.2f}")
""")

C_ROUNDTRIP = """
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "eyebot.h"

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e6 + ts.tv_nsec / 1e3;
}

int main(int argc, char **argv)
{
    int calls = atoi(argv[1]);
    for (int i = 0; i < 51; i++)
        OSGetCount();
    for (int i = 0; i < calls; i++) {
        double start = now_us();
        OSGetCount();
        printf("%.2f\\n", now_us() - start);
    }
    return 0;
}
"""


def round_trips() -> dict[str, dict]:
    BUILD.mkdir(parents=True, exist_ok=True)
    (BUILD / "count_roundtrip.c").write_text(C_ROUNDTRIP)
    c_program = build_c(BUILD / "count_roundtrip.c", BUILD / "count_roundtrip")
    (BUILD / "count_roundtrip.py").write_text(PYTHON_ROUNDTRIP)
    results = {}
    for name, command in (("c", [str(c_program)]), ("python", [sys.executable, str(BUILD / "count_roundtrip.py")])):
        simulator, port = start_simulator("--headless", "--clock", "realtime", "--call-time", "0")  # round trips only
        try:
            env = dict(os.environ, EYESIM_PORT=str(port))
            out = subprocess.run([*command, str(CALLS)], capture_output=True, text=True, check=True, env=env).stdout
        finally:
            stop(simulator)
        results[name] = summary([float(v) for v in out.split()])
    return results


def main() -> int:
    program = build_speed_program()
    results: dict = {"c": {name: c_speeds(program, code) for name, code in RESOLUTIONS.items()}}
    for name in RESOLUTIONS:
        speeds = results["c"][name]
        rows = [(f, f"{us:.0f}", f"{us / speeds['memcpy']:.1f}x") for f, us in speeds.items()]
        print_table(
            f"C image processing, {name} (microseconds per call, best of 5)", rows, ("function", "us", "vs memcpy")
        )
        print()
    results["python_layer"] = python_layer()
    rows = [
        (f, f"{r['eye_us']:.1f}", f"{r['ctypes_us']:.1f}", f"{r['eye_us'] / r['ctypes_us']:.2f}x")
        for f, r in results["python_layer"].items()
    ]
    print_table(
        "Python: through eye vs plain ctypes, QVGA (microseconds per call)",
        rows,
        ("function", "eye", "ctypes", "ratio"),
    )
    print()
    results["roundtrip"] = round_trips()
    c, py = results["roundtrip"]["c"], results["roundtrip"]["python"]
    rows = [
        (name, f"{r['median_ms'] * 1000:.0f}", f"{r['p99_ms'] * 1000:.0f}", f"{r['median_ms'] / c['median_ms']:.2f}x")
        for name, r in (("C", c), ("Python (eye)", py))
    ]
    print_table(
        f"OSGetCount round trip, {CALLS} calls, realtime (microseconds)",
        rows,
        ("program", "median", "p99", "median vs C"),
    )
    print(f"wrote {write_results('ip', results)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
