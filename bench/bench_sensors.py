"""Sensor costs: CAMGet QVGA frame rates with each renderer, lidar scan rates, and what PSDGet adds
to a call's round trip, each beside a baseline measured in the same run.

In-process: rendering one QVGA frame (OpenGL, ray caster) and one 360-point lidar scan in the
arena scene, against one physics step. Through the protocol (a C program against a headless
realtime `eyesim run`): PSDGet, LIDARGet and CAMGet against OSGetCount, the round trip of a call
that does no sensor work. Prints a table, writes bench/results/sensors.json."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

from common import BENCH, build_c, print_table, start_simulator, stop, summary, write_results

sys.path.insert(0, str(BENCH.parent))
sys.path.insert(0, str(BENCH.parent / "tests"))

CALLS = 1000  # protocol round trips per call kind
FRAMES = 100  # CAMGet frames through the protocol
IN_PROCESS_FRAMES = 60
SCANS = 2000
BUILD = BENCH / "results" / "build"


def best_time(action, repeat: int) -> float:
    """Seconds per call: the median of `repeat` timed calls (after a warm-up)."""
    action()
    samples = []
    for _ in range(repeat):
        start = time.perf_counter()
        action()
        samples.append(time.perf_counter() - start)
    return sorted(samples)[len(samples) // 2]


def in_process() -> dict:
    from support.scenes import arena

    from eyesim.core.engine import Simulation
    from eyesim.physics import render_gl
    from eyesim.physics.render_raycast import RayCastRenderer
    from eyesim.parts.camera.component import Camera
    from eyesim.parts.lidar.component import LidarScanner

    sim = Simulation(arena(robots=((500, 500, 0), (1500, 500, 180), (1000, 1500, 270))))
    robot = sim.robots[0]
    view = robot.component(Camera).view(320, 240)
    scanner = robot.component(LidarScanner)
    maze = Simulation(arena(robots=((250, 250, 45),), inner_walls=maze_walls()))
    maze_view = maze.robots[0].component(Camera).view(320, 240)
    gl = render_gl.GlRenderer(render_gl.choose_backend(os.environ.get("MUJOCO_GL", "").lower()))
    ray_caster = RayCastRenderer()

    def new_scan():  # as after a physics step: the scanner keeps only a scan of the same state
        sim.world.state_version += 1
        scanner.scan()

    return {
        "step_s": best_time(sim.step, 500),
        "render_opengl_s": best_time(lambda: gl.render(sim.world, view), IN_PROCESS_FRAMES),
        "render_raycast_s": best_time(lambda: ray_caster.render(sim.world, view), IN_PROCESS_FRAMES),
        "maze_opengl_s": best_time(lambda: gl.render(maze.world, maze_view), IN_PROCESS_FRAMES),
        "maze_raycast_s": best_time(lambda: ray_caster.render(maze.world, maze_view), IN_PROCESS_FRAMES),
        "maze_walls": len(maze.scene.world.walls),
        "lidar_scan_s": best_time(new_scan, SCANS),
        "opengl_backend": gl.backend,
    }


def maze_walls():
    """A 4 x 4 grid of 500 mm cells with every other inner wall: many walls, few in view at once."""
    from eyesim.scene.description import Wall

    walls = []
    for i in range(1, 4):
        for j in range(4):
            if (i + j) % 2:
                walls.append(Wall(i * 500, j * 500, i * 500, j * 500 + 500))
            else:
                walls.append(Wall(j * 500, i * 500, j * 500 + 500, i * 500))
    return walls


def through_protocol(program: Path, renderer_env: dict) -> dict:
    env = dict(os.environ, **renderer_env)
    # --call-time 0: what the sensors add to a round trip, not the per-call time (bench_call_time.py).
    simulator, port = start_simulator("--headless", "--clock", "realtime", "--call-time", "0", env=env)
    try:
        result = subprocess.run(
            [str(program), str(CALLS), str(FRAMES)],
            capture_output=True,
            text=True,
            check=True,
            env=dict(env, EYESIM_PORT=str(port)),
        )
    finally:
        stop(simulator)
    samples: dict[str, list[float]] = {}
    for line in result.stdout.splitlines():
        name, value = line.split()
        samples.setdefault(name, []).append(float(value))
    return {name: summary(values) for name, values in samples.items()}


def main() -> int:
    program = build_c(BENCH / "programs" / "sensor_rates.c", BUILD / "sensor_rates")
    local = in_process()
    opengl = through_protocol(program, {})
    raycast = through_protocol(program, {"MUJOCO_GL": "disable"})
    results = {"in_process": local, "protocol_opengl": opengl, "protocol_raycast": raycast}

    step = local["step_s"]
    rows = [
        ("physics step (baseline)", f"{step * 1e3:.3f} ms", "", "1.0x"),
        (
            f"render QVGA, OpenGL ({local['opengl_backend']})",
            f"{local['render_opengl_s'] * 1e3:.2f} ms",
            f"{1 / local['render_opengl_s']:.0f} fps",
            f"{local['render_opengl_s'] / step:.1f}x",
        ),
        (
            "render QVGA, ray caster",
            f"{local['render_raycast_s'] * 1e3:.2f} ms",
            f"{1 / local['render_raycast_s']:.0f} fps",
            f"{local['render_raycast_s'] / step:.1f}x",
        ),
        (
            f"render QVGA in a {local['maze_walls']}-wall maze, OpenGL",
            f"{local['maze_opengl_s'] * 1e3:.2f} ms",
            f"{1 / local['maze_opengl_s']:.0f} fps",
            f"{local['maze_opengl_s'] / step:.1f}x",
        ),
        (
            f"render QVGA in a {local['maze_walls']}-wall maze, ray caster",
            f"{local['maze_raycast_s'] * 1e3:.2f} ms",
            f"{1 / local['maze_raycast_s']:.0f} fps",
            f"{local['maze_raycast_s'] / step:.1f}x",
        ),
        (
            "lidar scan, 360 points",
            f"{local['lidar_scan_s'] * 1e3:.3f} ms",
            f"{1 / local['lidar_scan_s']:.0f} scans/s",
            f"{local['lidar_scan_s'] / step:.1f}x",
        ),
    ]
    print_table("In process (arena, 3 robots)", rows, ("what", "time", "rate", "vs physics step"))
    print()
    base = opengl["os_get_count"]["median_ms"]
    rows = [
        (
            "OSGetCount (baseline)",
            f"{base:.3f}",
            f"{opengl['os_get_count']['p99_ms']:.3f}",
            f"{opengl['os_get_count']['mean_ms']:.3f}",
            "",
            "1.00x",
        )
    ]
    measured = [
        ("PSDGet", opengl["psd_get"], "calls/s"),
        ("LIDARGet 360 points", opengl["lidar_get"], "scans/s"),
        ("LIDARGet, every scan cast anew", opengl["lidar_get_fresh"], "scans/s"),
        ("CAMGet QVGA, OpenGL", opengl["cam_get"], "fps"),
        ("CAMGet QVGA, ray caster", raycast["cam_get"], "fps"),
    ]
    for label, r, unit in measured:
        rows.append(
            (
                label,
                f"{r['median_ms']:.3f}",
                f"{r['p99_ms']:.3f}",
                f"{r['mean_ms']:.3f}",
                f"{1000 / r['mean_ms']:.0f} {unit}",
                f"{r['median_ms'] / base:.2f}x",
            )
        )
    print_table(
        f"Through the protocol, realtime ({CALLS} calls, {FRAMES} frames; ms)",
        rows,
        ("call", "median", "p99", "mean", "rate (1 / mean)", "median vs OSGetCount"),
    )
    print(
        "LIDARGet polled faster than the physics steps returns the scan made at the same state; "
        "'every scan cast anew' alternates it with SIMLaserScan, so that no scan is reused."
    )
    print(
        "targets: CAMGet QVGA >= 30 fps per renderer, lidar >= 2000 scans/s, PSDGet within 20% of the "
        "foundation's round trip (bench_roundtrip.py)"
    )
    print(f"wrote {write_results('sensors', results)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
