"""`eyesim.Simulation`: a simulator a test or a grader drives from Python (docs/testing.md).

It wraps the engine (`eyesim.core.engine.Simulation`, here `engine`) with what `eyesim run` adds —
the program server, the launcher, scripted input — and records what checks need: true paths,
contacts, serial output, radio messages, program output and exit codes. The engine runs in the
calling thread during `run()`; between runs everything can be read at leisure.

    with Simulation("lab.sim") as sim:
        sim.program(1, "./follow", "--fast")
        sim.key(1, "KEY4", at=20)
        sim.run(until=30)
        assert sim.robot(1).pose.distance_to(1000, 500) < 100
"""

from __future__ import annotations

import dataclasses
import shutil
import subprocess
import tempfile
import threading
from dataclasses import dataclass
from pathlib import Path

from eyesim.core import inputs
from eyesim.core.clock import DETERMINISTIC, Clock
from eyesim.core.engine import Simulation as Engine
from eyesim.core.stalls import StallWatch
from eyesim.net.program_server import ProgramServer
from eyesim.programs.launcher import Launcher, ProgramOptions
from eyesim.protocol import generated as g
from eyesim.robot.components.keys import KEY_NAMES
from eyesim.robot.components.serial_ports import SerialPorts
from eyesim.scene.description import Scene
from eyesim.testing.callable_program import start_callable, stop_callable
from eyesim.testing.contacts import ContactTracker
from eyesim.testing.observe import PathRecorder, RobotEvents, record_radio
from eyesim.testing.views import ObjectView, RobotView


class SimulationError(Exception):
    """Something the test asked for cannot be done (no such robot, a scene that does not load)."""


class CompileError(SimulationError):
    def __init__(self, source: str, output: str):
        super().__init__(f"{source} does not compile:\n{output}")
        self.output = output


@dataclass(frozen=True)
class RunEnd:
    """Why `run()` returned: 'time' (reached `until`), 'condition' (stop_when held), 'programs'
    (every program ended), 'watchdog' (wall_timeout passed), at simulation time `time` (s)."""

    reason: str
    time: float
    stalled: tuple[str, ...] = ()  # what the programs waited for when the run stood still (core/stalls.py)


class _ConditionMet(Exception):
    pass


def load_scene_argument(scene) -> Scene:
    """A Scene from a Scene, a file path, a bundled scene's name, or None (the default arena)."""
    from eyesim.scene import DEFAULT_SCENE, SceneError, builtins, load_scene

    if isinstance(scene, Scene):
        return scene
    try:
        return load_scene(builtins.scene_argument(str(scene)) if scene is not None else DEFAULT_SCENE)
    except SceneError as error:
        raise SimulationError("\n".join(str(d) for d in error.diagnostics) or f"cannot load {scene}") from None
    except OSError as error:
        raise SimulationError(f"cannot read scene {scene}: {error.strerror}") from None


class Simulation:
    """One simulated world with its programs. `scene`: a Scene built in code, a scene file, a
    bundled scene's name, or None for the default arena. `seed` and `psd_noise` replace the
    scene's settings. The clock is deterministic unless `clock='realtime'`. `echo` prints the
    programs' output as `eyesim run` does."""

    def __init__(
        self,
        scene=None,
        *,
        seed: int | None = None,
        psd_noise: float | None = None,
        clock: str = DETERMINISTIC,
        host: str = g.DEFAULT_HOST,
        echo: bool = False,
    ):
        scene = load_scene_argument(scene)
        changes = {key: value for key, value in (("seed", seed), ("psd_noise", psd_noise)) if value is not None}
        if changes:
            scene = dataclasses.replace(scene, settings=dataclasses.replace(scene.settings, **changes))
        self.scene = scene
        self.engine = Engine(scene, Clock(clock))
        self.host = host
        self._server = ProgramServer(self.engine, host, 0)  # served by the engine's own thread
        self._server.start()
        self.port = self._server.port
        # The run's program token: the programs this simulation starts get it (EYESIM_TOKEN); one
        # connecting by other means sends it in its HELLO (docs/running.md#the-program-token).
        self.program_token = self._server.token
        self._launcher = Launcher(self.engine, host, self.port, echo=echo)
        self._runs: dict = {}
        self._pending_programs: list = []  # (robot id, path or callable, options) until run() starts them
        self._workdirs: dict[int, Path] = {}
        self._tmp: Path | None = None
        self._paths = PathRecorder(self.engine)
        self._contacts = ContactTracker(self.engine)
        self._events = RobotEvents(self.engine)
        self.engine.events.subscribe(self._events)
        self.radio = record_radio(self.engine)  # observe.RadioMessage, in the order sent
        self._callbacks: list = []
        self.engine.step_observers += [self._paths, self._contacts, self._step_callbacks]
        self._started = False
        self._closed = False

    # -- what is in the world --------------------------------------------------------------------
    @property
    def time(self) -> float:
        """Simulation time in seconds."""
        return self.engine.time

    @property
    def robots(self) -> list[RobotView]:
        return [RobotView(self, robot) for robot in self.engine.robots]

    def robot(self, selector: int | str) -> RobotView:
        """A robot by its id (1..n in scene order) or its type name."""
        return RobotView(self, self._robot(selector))

    def object(self, object_id: int) -> ObjectView:
        thing = self.engine.object_by_id(object_id)
        if thing is None:
            raise SimulationError(f"no object {object_id}; the scene has {len(self.engine.objects)}")
        return ObjectView(self, thing)

    @property
    def objects(self) -> list[ObjectView]:
        return [ObjectView(self, thing) for thing in self.engine.objects]

    @property
    def contacts(self) -> list:
        """Every contact episode so far (contacts.Contact), in the order they began."""
        return list(self._contacts.contacts)

    @property
    def sounds(self) -> list[dict]:
        return list(self._events.sounds)

    def _robot(self, selector):
        engine = self.engine
        if isinstance(selector, int) or str(selector).isdigit():
            robot = engine.robot_by_id(int(selector))
        else:
            robot = next((r for r in engine.robots if r.name.lower() == str(selector).lower()), None)
        if robot is None:
            names = ", ".join(f"{r.id} ({r.name})" for r in engine.robots) or "none"
            raise SimulationError(f"no robot {selector!r} in the scene; robots: {names}")
        return robot

    # -- programs --------------------------------------------------------------------------------
    def program(
        self,
        robot,
        program,
        *args: str,
        stdin: str | bytes | None = None,
        cwd=None,
        env: dict | None = None,
        cpu_seconds: float | None = None,
        memory_bytes: int | None = None,
        own_group: bool = False,
        processes: int | None = None,
        file_bytes: int | None = None,
    ):
        """Run a program for a robot when the simulation starts: an executable, a `.py` file
        (run with this Python) or a Python callable `program(robot_client)` (callable_program.py).
        Programs start with the first `run()`; their results are read from `robot(n)`.
        `cpu_seconds`, `memory_bytes`, `processes` and `file_bytes` limit the program's process
        (platform.Limits); `own_group` gives it a process group of its own, stopped as a whole
        (launcher.ProgramOptions)."""
        robot_id = self._robot(robot).id
        if robot_id in self._runs or any(r == robot_id for r, *_ in self._pending_programs):
            raise SimulationError(f"robot {robot_id} already has a program")
        if callable(program):
            self._pending_programs.append((robot_id, program, None))
        else:
            path = Path(program)
            if not path.is_file():
                raise SimulationError(f"program not found: {program}")
            options = ProgramOptions(
                tuple(str(a) for a in args),
                stdin,
                cwd,
                dict(env or {}),
                cpu_seconds,
                memory_bytes,
                own_group,
                processes,
                file_bytes,
            )
            self._pending_programs.append((robot_id, path, options))
        if self._started:
            self._start_programs()

    def c_program(self, robot, source: str | Path, *args: str, flags=("-O2",), language: str = "cc", **options):
        """Compile a C (language='c++': C++) program with `eyesim cc` and run it for the robot.
        `source`: a file, or the program's text. Raises CompileError with the compiler's output."""
        directory = self.temporary_directory() / f"robot{self._robot(robot).id}-build"
        directory.mkdir(exist_ok=True)
        if isinstance(source, Path) or (isinstance(source, str) and "\n" not in source and Path(source).is_file()):
            source_file = Path(source)
        else:
            source_file = directory / ("program.c" if language == "cc" else "program.cpp")
            source_file.write_text(source)
        executable = compile_program(source_file, directory / "program", flags, language)
        return self.program(robot, executable, *args, **options)

    def temporary_directory(self) -> Path:
        """A directory of this simulation's own, removed by close()."""
        if self._tmp is None:
            self._tmp = Path(tempfile.mkdtemp(prefix="eyesim-sim-"))
        return self._tmp

    def _start_programs(self) -> None:
        pending, self._pending_programs = self._pending_programs, []
        for robot_id, program, options in pending:
            if options is None:
                self._runs[robot_id] = start_callable(self.engine, self.host, self.port, robot_id, program)
            else:
                self._runs[robot_id] = self._launcher.start(robot_id, program, options)
                self._workdirs[robot_id] = Path(options.cwd or Path(program).resolve().parent)

    # -- input at simulation times -------------------------------------------------------------
    def at(self, seconds: float, action) -> None:
        """Run `action(engine)` at the first physics step at or after `seconds`."""
        self.engine.schedule(round(seconds * 1e6), action)

    def key(self, robot, key: str | int, at: float) -> None:
        code = KEY_NAMES.get(str(key).upper()) if not isinstance(key, int) else key
        if code is None:
            raise SimulationError(f"{key!r} is not KEY1..KEY4")
        self._input(robot, at, type="key", key=code)

    def touch(self, robot, x: int, y: int, at: float) -> None:
        self._input(robot, at, type="touch", x=x, y=y)

    def irtv(self, robot, button: str, at: float) -> None:
        self._input(robot, at, type="irtv", code=button)

    def serial(self, robot, interface: int, data: str | bytes, at: float) -> None:
        text = data if isinstance(data, str) else bytes(data).decode("latin-1")
        self._input(robot, at, type="serial", interface=interface, text=text)

    def serial_loopback(self, robot, interface: int) -> None:
        self._robot(robot).component(SerialPorts).port(interface).loopback = True

    def digital(self, robot, line: int, level: int | None, at: float) -> None:
        self._input(robot, at, type="digital", line=line, level=level)

    def analog(self, robot, channel: int, value: int, at: float) -> None:
        self._input(robot, at, type="analog", channel=channel, value=value)

    def _input(self, robot, at: float, **command) -> None:
        """An input of eyesim.core.inputs (the browser's and `eyesim run`'s table and checks) at a time."""
        try:
            self.at(at, inputs.prepare(self.engine, {**command, "robot": self._robot(robot).id}))
        except inputs.InputError as error:
            raise SimulationError(str(error)) from None

    # -- running ---------------------------------------------------------------------------------
    def every_step(self, callback) -> None:
        """Call `callback(sim)` after every physics step (2 ms), on the simulation thread; checks
        during the run go here. An exception it raises ends `run()` and is raised from it."""
        self._callbacks.append(callback)

    def _step_callbacks(self, engine) -> None:
        for callback in self._callbacks:
            callback(self)
        if self._stop_when is not None and self._stop_when(self):
            raise _ConditionMet

    _stop_when = None

    def run(
        self,
        until: float | None = None,
        *,
        stop_when=None,
        end_with_programs: bool = True,
        wall_timeout: float | None = None,
    ) -> RunEnd:
        """Simulate until `until` seconds of simulation time, until `stop_when(sim)` holds after
        a step, or (with `end_with_programs`, the default) until every program has ended —
        whichever comes first. Without `until` and without programs, `stop_when` is needed.
        `wall_timeout`: seconds of real time after which programs are killed and the run ends
        (a program that computes without calling RoBIOS holds deterministic time still)."""
        if self._closed:
            raise SimulationError("the simulation is closed")
        has_programs = bool(self._runs or self._pending_programs)
        if until is None and stop_when is None and not (has_programs and end_with_programs):
            raise SimulationError("run() needs `until`, `stop_when` or programs to wait for")
        if not self._started:
            self._started = True
            self._start_programs()
        self.engine.stop_when_programs_done = bool(end_with_programs and self._runs)
        self.engine.call(lambda s: s.check_programs_done())
        self._stop_when = stop_when
        timer = None
        watchdog = threading.Event()
        if wall_timeout is not None:
            timer = threading.Timer(wall_timeout, self._watchdog, args=(watchdog,))
            timer.daemon = True
            timer.start()
        reason = None
        stalled: list[str] = []
        watch = StallWatch(self.engine, stalled.extend, keys_can_come=False).start()
        try:
            self.engine.run(until=until)
        except _ConditionMet:
            reason = "condition"
        finally:
            self._stop_when = None
            watch.stop()
            if timer is not None:
                timer.cancel()
        if reason is None:
            if watchdog.is_set():
                reason = "watchdog"
            elif until is not None and self.engine.time_us >= round(until * 1e6):
                reason = "time"
            else:
                reason = "programs"
        # Programs whose connections closed are exiting: take in their exit codes and output.
        self._launcher.settle(wait=5.0 if reason in ("programs", "watchdog") else 0.0)
        for run in self._runs.values():
            if not hasattr(run, "process") and reason == "programs" and run.thread is not None:
                run.thread.join(timeout=5.0)
        return RunEnd(reason, self.time, tuple(stalled))

    def _watchdog(self, fired: threading.Event) -> None:
        fired.set()
        for run in list(self._runs.values()):
            if hasattr(run, "process"):
                self._launcher.kill(run)
            else:
                run.stopped_by_us = True
                if run.client is not None:
                    run.client.close()
        self.engine.stop()

    # -- the end ---------------------------------------------------------------------------------
    def stop_programs(self) -> None:
        """End the run for the programs: those still running are stopped (and not counted as
        failed), and everything they printed is taken in. The world stays readable."""
        self._launcher.stop_all(let_finish=0.0)
        for run in self._runs.values():
            if not hasattr(run, "process"):
                stop_callable(run)

    def close(self) -> None:
        """Stop the programs still running (not counted as failed), the server and threads."""
        if self._closed:
            return
        self._closed = True
        self.stop_programs()
        self._server.stop()
        self.engine.close()
        if self._tmp is not None:
            shutil.rmtree(self._tmp, ignore_errors=True)

    def __enter__(self) -> "Simulation":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def compile_program(source: Path, output: Path, flags=("-O2",), language: str = "cc") -> Path:
    """`eyesim cc` (or `eyesim c++`) a source file; raises CompileError with the compiler's output."""
    from eyesim.programs import toolchain

    output = toolchain.executable_name(Path(output))
    args = [*flags, str(source), "-o", str(output)]
    try:
        command = toolchain.compiler_command(language, args)
    except (toolchain.LibraryMissing, toolchain.CompilerMissing) as error:
        raise SimulationError(str(error)) from None
    try:
        result = subprocess.run(command, capture_output=True, text=True)
    except FileNotFoundError:
        raise SimulationError(f"compiler {command[0]!r} not found") from None
    if result.returncode != 0:
        raise CompileError(str(source), result.stdout + result.stderr)
    toolchain.place_library(args)
    return output


__all__ = ["Simulation", "SimulationError", "CompileError", "RunEnd", "compile_program"]
