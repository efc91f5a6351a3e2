"""Benchmark: real-time factor of the simulation loop with 1, 10, 50 and 100 S4 robots driving
under VW control, beside MuJoCo's bare mj_step on the same model in the same run.

Run:  PYTHONPATH=src python3 bench/bench_realtime_factor.py [--robots 1 10 50 100] [--seconds 2] [--repeats 3]
Prints a table and writes bench/results/realtime_factor.json.

The simulation runs as `eyesim run --speed max` does (realtime clock, as fast as possible) for
`--seconds` of wall time per measurement, best of three. Instead of one program process per robot,
a driver in the same process gives each robot its next manoeuvre (300 mm straight, 90 degree turn:
squares, each robot in its own 600 mm cell) through the VW controller the handlers use, so what is
measured is the simulator, not the scheduling of 100 processes on a small machine. The baseline is
mj_step alone through the same states, for as many steps, measured between the runs (see bare_steps).
Targets (performance issue): >= 120x real time for one robot with our overhead per step <= 0.4x
mj_step's cost, >= 2x real time for 100 robots. The machine is shared: compare runs of the same
session only, and repeat.
"""

from __future__ import annotations

import argparse
import copy
import math
import sys
import time
from collections import defaultdict
from pathlib import Path

import mujoco

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import print_table, write_results  # noqa: E402

from eyesim.core.clock import MAX_SPEED, Clock  # noqa: E402
from eyesim.core.engine import Simulation  # noqa: E402
from eyesim.robot.components.vw import VwController  # noqa: E402
from eyesim.scene import load_robot_type  # noqa: E402
from eyesim.scene.description import Pose, RobotPlacement, Scene, Wall, World  # noqa: E402

CELL = 600  # mm of floor per robot
SIDE = 0.3  # m of each square's side
REPEATS = 3  # best of (--repeats): the machine is shared


def square_drivers_scene(count: int) -> Scene:
    columns = math.ceil(math.sqrt(count))
    size = columns * CELL
    walls = (Wall(0, 0, size, 0), Wall(size, 0, size, size), Wall(size, size, 0, size), Wall(0, size, 0, 0))
    s4 = load_robot_type("S4")
    placements = tuple(
        RobotPlacement(s4.name, Pose(CELL * (i % columns) + 150, CELL * (i // columns) + 150, 0)) for i in range(count)
    )
    return Scene("bench", World("bench", size, size, walls), robot_types={s4.name: s4}, robots=placements)


class SquareDriver:
    """After every step, gives each robot whose manoeuvre is done the next one of its square: a turn
    to face the square's next corner, then a straight to it, aimed from the robot's true pose (as a
    program would with SIMGetRobot), so that the manoeuvres' small errors do not add up: squares
    driven blind drift, and after a few hundred the robot is jammed in its cell's corner."""

    def __init__(self, sim: Simulation):
        self.robots = sim.robots
        self.controllers = [robot.component(VwController) for robot in sim.robots]
        self.legs = [0] * len(self.controllers)
        self.corners = []
        for robot in self.robots:
            x, y, _, _ = robot.pose()
            self.corners.append([(x + dx, y + dy) for dx, dy in ((0, 0), (SIDE, 0), (SIDE, SIDE), (0, SIDE))])

    def __call__(self, sim: Simulation) -> None:
        # It stands in for the robots' programs, whose commands cost the simulator nothing between
        # them: it only looks (the `manoeuvre` attribute: the `done` property would cost more).
        index = 0
        for vw in self.controllers:
            if vw.manoeuvre is None:
                self.next_leg(index, vw)
            index += 1

    def next_leg(self, index: int, vw: VwController) -> None:
        leg = self.legs[index]
        self.legs[index] += 1
        x, y, _, heading = self.robots[index].pose()
        corner_x, corner_y = self.corners[index][((leg + 1) // 2 + 1) % 4]
        if leg % 2 == 0:
            vw.straight(math.hypot(corner_x - x, corner_y - y), 0.3)
        else:
            turn = math.atan2(corner_y - y, corner_x - x) - heading
            vw.turn(math.remainder(turn, 2 * math.pi), math.radians(120))


def run_for_wall_time(sim: Simulation, wall_seconds: float) -> tuple[float, int, float]:
    """The simulation loop, in growing slices of simulated time until `wall_seconds` have passed;
    returns (wall s, steps, simulated s)."""
    wall, steps, simulated = 0.0, 0, 0.0
    slice_seconds = 0.02
    while wall < wall_seconds:
        start_steps, start_us = sim.steps, sim.time_us
        start = time.perf_counter()
        sim.run(until=sim.time + slice_seconds)
        elapsed = time.perf_counter() - start
        wall += elapsed
        steps += sim.steps - start_steps
        simulated += (sim.time_us - start_us) / 1e6
        if elapsed < 0.2:
            slice_seconds *= 2
    return wall, steps, simulated


def bare_steps(sim: Simulation, steps: int) -> float:
    """Wall seconds of `steps` bare mj_step calls through the states the loop itself goes through.

    The loop runs the next `steps` steps first (untimed), noting the motors' controls before each;
    then mj_step alone replays them from a copy of the starting state, setting the controls where
    they changed, and must end in the very state the loop reached. (Stepping a copy with the
    controls left as they were is no baseline: the robots drive off their squares into the walls
    and each other, and pushing against a wall costs MuJoCo a third more.) The replay's own
    bookkeeping, timed with a step that does nothing, is taken off."""
    model, data = sim.world.model, sim.world.data
    start = copy.copy(data)
    changes = []  # (step index, the controls from then on)
    recorded = 0

    def recording_step():
        nonlocal recorded
        controls = data.ctrl.tolist()
        if not changes or controls != changes[-1][1]:
            changes.append((recorded, controls))
        recorded += 1
        mujoco.mj_step(model, data)

    sim.world.step = recording_step  # in place of the world's own step, for this run only
    try:
        sim.run(until=(sim.time_us + steps * sim.step_us) / 1e6)
    finally:
        del sim.world.step
    if recorded != steps:
        raise RuntimeError(f"the loop took {recorded} steps, not {steps}")

    def replay(step) -> tuple[float, mujoco.MjData]:
        state = copy.copy(start)
        ctrl = state.ctrl
        pending = iter(changes)
        at, controls = next(pending)
        begin = time.perf_counter()
        for index in range(steps):
            if index == at:
                ctrl[:] = controls
                at, controls = next(pending, (-1, None))
            step(model, state)
        return time.perf_counter() - begin, state

    bare, state = replay(mujoco.mj_step)
    if not (state.qpos == data.qpos).all():
        raise RuntimeError("replaying the controls did not go through the loop's states")
    bookkeeping, _ = replay(lambda model, state: None)
    return bare - bookkeeping


def hook_costs(sim: Simulation, steps: int) -> dict[str, float]:
    """Microseconds per robot per step of each component kind's step hooks and ticks, timed where they run
    (in the loop, the robots driving: called on their own, a VW controller would stop at once),
    less the cost of timing a hook that does nothing."""
    spent = defaultdict(float)
    clock = time.perf_counter

    def timed(kind, hook):
        def call(dt):
            start = clock()
            hook(dt)
            spent[kind] += clock() - start

        return call

    idle = timed("idle", lambda dt: None)
    for _ in range(10000):
        idle(0.002)
    timing = spent.pop("idle") / 10000
    before, after, ticks = sim._before_step, sim._after_step, sim._tick
    sim._before_step = [timed(type(h.__self__).__name__, h) for h in before]
    sim._after_step = [timed(type(h.__self__).__name__, h) for h in after]
    sim._tick = [timed(type(h.__self__).__name__, h) for h in ticks]
    calls = defaultdict(float)  # per step
    for hook in before + after:
        calls[type(hook.__self__).__name__] += 1
    for hook in ticks:
        calls[type(hook.__self__).__name__] += 1 / sim._tick_steps
    try:
        start = sim.steps
        sim.run(until=sim.time + steps * sim.step_us / 1e6)
        done = sim.steps - start
    finally:
        sim._before_step, sim._after_step, sim._tick = before, after, ticks
    return {
        kind: max(0.0, (total / done - timing * calls[kind]) / len(sim.robots) * 1e6)
        for kind, total in sorted(spent.items())
    }


def measure(count: int, wall_seconds: float, repeats: int = REPEATS) -> dict:
    sim = Simulation(square_drivers_scene(count), Clock("realtime", MAX_SPEED))
    sim.step_observers.append(SquareDriver(sim))
    sim.run(until=0.5)  # under way
    loop, bare = [], []  # seconds per step, measured alternately
    for _ in range(repeats):
        wall, steps, simulated = run_for_wall_time(sim, wall_seconds)
        loop.append(wall / steps)
        bare.append(bare_steps(sim, steps) / steps)
    step, mj_step = min(loop), min(bare)
    overhead = step - mj_step
    dt = sim.step_us / 1e6
    return {
        "robots": count,
        "real_time_factor": dt / step,
        "bare_real_time_factor": dt / mj_step,
        "step_us": step * 1e6,
        "mj_step_us": mj_step * 1e6,
        "overhead_per_robot_us": overhead / count * 1e6,
        "mj_step_per_robot_us": mj_step / count * 1e6,
        "overhead_ratio": overhead / mj_step,
        "components_per_robot_us": hook_costs(sim, max(200, round(0.5 / step))),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--robots", type=int, nargs="+", default=[1, 10, 50, 100])
    parser.add_argument("--seconds", type=float, default=2.0, help="wall time per measurement")
    parser.add_argument(
        "--repeats",
        type=int,
        default=REPEATS,
        help="measurements of each, the best counts (on a busy machine: many short ones)",
    )
    args = parser.parse_args()
    results = [measure(count, args.seconds, args.repeats) for count in args.robots]
    rows = [
        (
            r["robots"],
            f"{r['real_time_factor']:.1f}x",
            f"{r['bare_real_time_factor']:.1f}x",
            f"{r['step_us']:.0f}",
            f"{r['mj_step_us']:.0f}",
            f"{r['overhead_per_robot_us']:.1f}",
            f"{r['mj_step_per_robot_us']:.1f}",
            f"{r['overhead_ratio']:.2f}",
        )
        for r in results
    ]
    print_table(
        "Real-time factor, S4 robots driving squares under VW control (--speed max)",
        rows,
        (
            "robots",
            "real time",
            "bare mj_step",
            "step us",
            "mj_step us",
            "ours/robot us",
            "mujoco/robot us",
            "ours/mujoco",
        ),
    )
    print()
    kinds = sorted({kind for r in results for kind in r["components_per_robot_us"]})
    print_table(
        "Step hooks per robot and step (us), by component kind, timed in the loop",
        [(r["robots"], *(f"{r['components_per_robot_us'].get(kind, 0):.2f}" for kind in kinds)) for r in results],
        ("robots", *kinds),
    )
    by_count = {r["robots"]: r for r in results}
    targets = []
    if 1 in by_count:
        targets.append(("one robot >= 120x real time", by_count[1]["real_time_factor"] >= 120))
        targets.append(("one robot: our overhead <= 0.4x mj_step", by_count[1]["overhead_ratio"] <= 0.4))
    if 100 in by_count:
        targets.append(("100 robots >= 2x real time", by_count[100]["real_time_factor"] >= 2))
    print()
    for name, met in targets:
        print(f"{'met ' if met else 'MISSED'}  {name}")
    path = write_results("realtime_factor", {"results": results, "targets": dict(targets)})
    print(f"\nwritten to {path}")


if __name__ == "__main__":
    main()
