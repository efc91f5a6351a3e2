"""Fixed deterministic runs and a digest of everything they did, for tests/core/test_same_trajectories.py.

Each run is an `eyesim.Simulation` with real programs (C programs built with `eyesim cc`, and
Python callables), chosen to take every path of the request scheduler: several programs ordered by
(time, robot id), blocking calls (VWWait, OSWait, KEYWait) and a scripted key, camera images made
on the render thread, timer callbacks beside a polling main loop. What is digested, exactly:
the physics state (MuJoCo's qpos and qvel, as their bytes) after every step, and every answered
request with its simulation time, robot, operation, arguments and reply values (but the HELLO:
programs connect in the order the operating system starts them, with their own process id). Camera images
are drawn by the CPU ray caster (MUJOCO_GL=disable, set by the caller) so that the digest does not
depend on an OpenGL driver.

    python tests/core/deterministic_runs.py          # prints the digests as JSON
    python tests/core/deterministic_runs.py --write  # stores them in trajectories.json

The stored digests were made by the engine before it was split (commit 3601fe5); a change that
means to alter the simulation (a new MuJoCo, a changed physics or cost) writes them again."""

from __future__ import annotations

import hashlib
import json
import sys
import tempfile
from pathlib import Path

import mujoco

from eyesim.paths import EXAMPLES_DIR
from eyesim.testing import Simulation, compile_program

HERE = Path(__file__).resolve().parent
FIXTURE = HERE / "trajectories.json"
SCENES = EXAMPLES_DIR / "scenes"
PROGRAMS = EXAMPLES_DIR / "programs"


class Digest:
    """Step and request observer of one engine: hashes the state after each step and each answer."""

    def __init__(self, engine):
        self.engine = engine
        self.state = hashlib.sha256()
        self.requests = hashlib.sha256()
        self.answered = 0
        engine.step_observers.append(self.after_step)
        engine.request_observers.append(self.on_request)

    def after_step(self, engine) -> None:
        data = engine.world.data
        self.state.update(engine.time_us.to_bytes(8, "little"))
        self.state.update(data.qpos.tobytes())
        self.state.update(data.qvel.tobytes())

    def on_request(self, robot, request, values) -> None:
        if request.op.name == "HELLO":  # its pid and token, and the order programs connect in, vary
            return
        self.answered += 1
        line = (request.time_us, robot.id, request.op.name, request.args, values)
        self.requests.update(repr(line).encode())

    def result(self, end) -> dict:
        return {
            "end": end.reason,
            "time_us": self.engine.time_us,
            "steps": self.engine.steps,
            "answered": self.answered,
            "state": self.state.hexdigest(),
            "requests": self.requests.hexdigest(),
        }


def run(sim: Simulation, until: float) -> dict:
    digest = Digest(sim.engine)
    with sim:
        end = sim.run(until=until)
        result = digest.result(end)
        result["lcd"] = [robot.lcd_text() for robot in sim.robots]
    return result


def wall_follow(build) -> dict:
    sim = Simulation(SCENES / "wall_follow.sim")
    sim.program(1, build(PROGRAMS / "wall_follow.c"))
    return run(sim, 5)


def radio(build) -> dict:
    """Two programs talking over the radio: their calls interleave by (time, robot id)."""
    sim = Simulation(SCENES / "radio.sim")
    sim.program(1, build(PROGRAMS / "radio_commander.c"))
    sim.program(2, build(PROGRAMS / "radio_driver.c"))
    return run(sim, 6)


def colour_track(build) -> dict:
    """Camera images, made on the render thread, their replies at exactly their time."""
    sim = Simulation(SCENES / "colour_track.sim")
    sim.program(1, build(PROGRAMS / "colour_track.c"))
    return run(sim, 8)


def timer(build) -> dict:
    """Timer callbacks that call the API beside a main thread's waits and readings (run until it ends)."""
    sim = Simulation(SCENES / "wall_follow.sim")
    sim.program(1, build(HERE / "programs" / "timer_and_waits.c"))
    return run(sim, 10)


def square(robot):
    """Drives a square with VWStraight/VWTurn and VWWait, reading a PSD after each side."""
    readings = []
    for _ in range(4):
        robot.VWStraight(300, 200)
        robot.VWWait()
        readings.append(robot.PSDGet(1))
        robot.VWTurn(90, 90)
        robot.VWWait()
    robot.LCDPrintf("%s\n" % readings)


def poll_then_key(robot):
    """Polls sensors and the clock between short waits, then waits for a key pressed by script."""
    for _ in range(40):
        robot.PSDGet(2)
        robot.OSGetCount()
        robot.LCDPixel(1, 1, 0xFFFFFF)
        robot.OSWait(7)
    key = robot.KEYWait(0xFF)
    robot.VWSetSpeed(150, 30)
    robot.OSWait(500)
    robot.LCDPrintf("key %d at %d\n" % (key, robot.OSGetCount()))


def callables(_build) -> dict:
    """Two Python programs at once, blocking calls, local calls and a scripted key."""
    sim = Simulation(SCENES / "radio.sim")
    sim.program(1, square)
    sim.program(2, poll_then_key)
    sim.key(2, "KEY2", at=1.234)
    return run(sim, 12)


RUNS = {
    "wall_follow": wall_follow,
    "radio": radio,
    "colour_track": colour_track,
    "timer": timer,
    "callables": callables,
}


def digests() -> dict:
    with tempfile.TemporaryDirectory() as folder:

        def build(source: Path) -> Path:
            return compile_program(source, Path(folder) / source.stem)

        return {"mujoco": mujoco.__version__, "runs": {name: make(build) for name, make in RUNS.items()}}


if __name__ == "__main__":
    found = digests()
    text = json.dumps(found, indent=1, sort_keys=True) + "\n"
    if "--write" in sys.argv:
        FIXTURE.write_text(text)
    print(text, end="")
