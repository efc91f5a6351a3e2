"""`eyesim run` carried out (its options are in run.py): load a scene, serve programs and the viewer,
start the scene's programs, simulate."""

from __future__ import annotations

import contextlib
import dataclasses
import gc
import logging
import sys
import threading
import webbrowser

from eyesim import platform
from eyesim.app import scripted_input
from eyesim.app.robot_log import RobotLog
from eyesim.core.clock import DETERMINISTIC, MAX_SPEED, REALTIME, Clock
from eyesim.core.engine import Simulation
from eyesim.core.stalls import StallWatch
from eyesim.net.program_server import ProgramServer
from eyesim.net.program_token import TokenFile
from eyesim.programs.launcher import Launcher
from eyesim.scene import SceneError
from eyesim.scene.sim import MAX_CALL_TIME_MS


class UsageError(Exception):
    pass


def parse_speed(text: str) -> float:
    if text == "max":
        return MAX_SPEED
    try:
        speed = float(text)
    except ValueError:
        raise UsageError(f"--speed {text!r}: expected a number or 'max'") from None
    if not speed > 0:
        raise UsageError(f"--speed {text!r}: must be positive")
    return speed


def find_robot(sim: Simulation, selector: str):
    if selector.isdigit() and sim.robot_by_id(int(selector)):
        return sim.robot_by_id(int(selector))
    for robot in sim.robots:
        if robot.name.lower() == selector.lower():
            return robot
    names = ", ".join(f"{r.id} ({r.name})" for r in sim.robots) or "none"
    raise UsageError(f"no robot {selector!r} in the scene; robots: {names}")


def parse_program(sim: Simulation, text: str) -> tuple[int, str]:
    selector, sep, path = text.partition("=")
    if not sep or not path:
        raise UsageError(f"--program {text!r}: expected ROBOT=PATH, e.g. 1=./drive")
    return find_robot(sim, selector).id, path


def load(path: str | None):
    from eyesim.scene import DEFAULT_SCENE, SceneError, builtins, load_scene

    try:
        scene = load_scene(builtins.scene_argument(path) if path else DEFAULT_SCENE)
    except SceneError as error:
        for diagnostic in error.diagnostics:
            print(diagnostic, file=sys.stderr)
        raise UsageError(f"cannot load {path}") from None
    except OSError as error:
        raise UsageError(f"cannot read {path}: {error.strerror}") from None
    for warning in scene.warnings:
        print(warning, file=sys.stderr)
    return scene


def with_settings(scene, args):
    """The scene with the settings given on the command line in place of its own."""
    changes = {}
    if args.psd_noise is not None:
        if not args.psd_noise >= 0:
            raise UsageError(f"--psd-noise {args.psd_noise}: must be 0 or more (mm)")
        changes["psd_noise"] = args.psd_noise
    if args.seed is not None:
        changes["seed"] = args.seed
    if args.eyesim6_psd:
        changes["eyesim6_psd"] = True
    if args.call_time is not None:
        if not 0 <= args.call_time <= MAX_CALL_TIME_MS:
            raise UsageError(f"--call-time {args.call_time:g}: must be from 0 to {MAX_CALL_TIME_MS} (ms)")
        changes["call_time"] = args.call_time
    return dataclasses.replace(scene, settings=dataclasses.replace(scene.settings, **changes)) if changes else scene


def status_line(robot, run) -> str:
    x, y, _, phi = robot.pose_mm()
    line = f"robot {robot.id} {robot.name}: x={x:.0f} mm y={y:.0f} mm phi={phi:.1f} deg"
    if run is None:
        return line + ", no program"
    if run.error:
        return line + f", program {run.name}: {run.error}"
    if run.stopped_by_us:
        return line + f", program {run.name}: still running at the end (stopped)"
    if run.crash is not None:
        return line + f", program {run.name}: {run.crash}"
    return line + f", program {run.name}: exit code {run.exit_code}"


def main(args) -> int:
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING, format="eyesim: %(message)s")
    try:
        with contextlib.ExitStack() as cleanup:  # what the run leaves behind, however it ends
            return simulate(args, cleanup)
    except UsageError as error:
        print(f"eyesim run: {error}", file=sys.stderr)
        return 2


def simulate(args, cleanup: contextlib.ExitStack) -> int:
    speed = parse_speed(args.speed)
    if args.wall_limit is not None and not args.wall_limit > 0:
        raise UsageError(f"--wall-limit {args.wall_limit:g}: expected a positive number of seconds")
    mode = args.clock or (DETERMINISTIC if args.headless else REALTIME)
    scene = with_settings(load(args.scene), args)
    try:
        sim = Simulation(scene, Clock(mode, speed))
    except SceneError as error:  # a limit only the built world shows (the models' triangles together)
        for diagnostic in error.diagnostics:
            print(diagnostic, file=sys.stderr)
        raise UsageError(f"cannot build the world of {args.scene or 'the scene'}") from None
    programs: dict[int, str] = {}
    for robot, placement in zip(sim.robots, scene.robots):
        if placement.program:
            programs[robot.id] = placement.program
    for text in args.program:
        robot_id, path = parse_program(sim, text)
        programs[robot_id] = path
    try:
        scripted_input.schedule_inputs(sim, args, lambda selector: find_robot(sim, selector))
    except ValueError as error:
        raise UsageError(str(error)) from None
    robot_log = RobotLog() if args.headless else None  # the viewer shows serial output and plays sounds
    if robot_log is not None:
        sim.events.subscribe(robot_log)

    io = None  # the viewer's thread; programs are served by the simulation thread itself
    try:
        server = ProgramServer(sim, args.host, args.port, require_token=not args.no_token)
    except ValueError as error:  # --no-token on an address other machines reach
        raise UsageError(str(error)) from None
    token_file = None

    def before_listening(port: int) -> None:  # the file is there before any program can connect
        nonlocal token_file
        token_file = write_token_file(sim, server.token, port)
        if token_file is not None:
            cleanup.callback(token_file.remove)

    try:
        server.start(before_listening)
    except OSError as error:
        raise UsageError(
            f"cannot listen for programs on {args.host}:{args.port}: {error.strerror} "
            f"(is another simulator running? try --port 0)"
        ) from None
    launcher = Launcher(sim, args.host, server.port)
    viewer = None
    if not args.headless:
        from eyesim.web.server import ViewerServer

        from eyesim.web.io_thread import IoThread  # the viewer's asyncio: not imported by headless runs

        io = IoThread()
        io.start()
        try:
            viewer = ViewerServer(
                sim, io, args.host, args.viewer_port, launcher=launcher, require_token=not args.no_token
            )
        except ValueError as error:  # --no-token on an address other machines reach
            raise UsageError(str(error)) from None
        viewer.workspace = scene_workspace(sim, launcher, args)
        try:
            viewer.start()
        except OSError as error:
            raise UsageError(
                f"cannot serve the viewer on port {args.viewer_port}: {error.strerror} (try --viewer-port 0)"
            ) from None
        print(f"EyeSim viewer: {viewer.url}", flush=True)
        if viewer.access.token and not viewer.access.loopback:
            print(
                "EyeSim: the viewer is reachable from other machines; open it with the URL above "
                "(it carries the access token)",
                flush=True,
            )
        if args.open and platform.has_display():
            webbrowser.open(viewer.url)
    print(
        f"EyeSim: {len(sim.robots)} robot(s), programs connect to {args.host}:{server.port} "
        f"({mode} clock{'' if speed == 1 else f', speed {args.speed}'})",
        flush=True,
    )
    if token_file is not None:
        print(f"EyeSim: program token for programs started by hand (as this user): {token_file.path}", flush=True)

    recorders = start_recorders(sim, args)
    for robot_id, path in sorted(programs.items()):
        launcher.start(robot_id, path)
    # Headless with programs and no time limit: the run ends when the last program is done.
    sim.stop_when_programs_done = bool(args.headless and programs and args.until is None)
    sim.call(lambda s: s.check_programs_done())  # e.g. no program could start
    interrupted = False
    watch = None
    if sim.clock.deterministic or args.headless:
        watch = StallWatch(sim, _say_why_the_run_stands_still, keys_can_come=not args.headless).start()
    wall_limit = _wall_limit(sim, args.wall_limit)
    memory_trim = _MemoryTrim()
    # What is set up by now (modules, the scene's world and robots) lives as long as the run: kept
    # out of Python's full garbage collections, which walked all of it on the simulation thread
    # (30-60 ms pauses under a flood of connections; 7-15 ms with it frozen). A new scene: engine.py.
    gc.freeze()
    try:
        sim.run(until=args.until)
    except KeyboardInterrupt:
        print("\neyesim: interrupted", file=sys.stderr)
        interrupted = True
    finally:
        if watch is not None:
            watch.stop()
        if wall_limit is not None:
            wall_limit.cancel()
        memory_trim.stop()
        launcher.stop_all(let_finish=5.0 if sim.stop_when_programs_done else 0.0)
        sim.shutdown_programs()
        sim.handle_queued()
        server.stop()
        if viewer is not None:
            viewer.stop()
        if io is not None:
            io.stop()
        for recorder in recorders:
            recorder.close()
        if robot_log is not None:
            robot_log.flush()
    if args.save_lcd:
        from eyesim.record import save_lcd_images

        save_lcd_images(sim, args.save_lcd)
    runs = {run.robot_id: run for run in launcher.runs}
    if args.headless or args.until is not None:
        print(f"EyeSim: stopped at t={sim.time:.3f} s")
        for robot in sim.robots:
            print(status_line(robot, runs.get(robot.id)))
    if interrupted:
        return 130  # Ctrl-C: the shell's status for SIGINT
    if wall_limit is not None and wall_limit.reached:
        return 1
    return 1 if any(run.failed for run in launcher.runs) else 0


def write_token_file(sim, token: str | None, port: int) -> TokenFile | None:
    """The run's program token in the file programs started by hand read (net/program_token.py);
    None without a token, or when it cannot be written (said once: such programs then need
    EYESIM_TOKEN)."""
    if token is None:
        return None
    token_file = TokenFile(token, port)
    try:
        token_file.write()
    except OSError as error:
        print(
            f"eyesim: cannot write the program token to {token_file.path} ({error.strerror}); a program "
            f"started by hand needs EYESIM_TOKEN={token}",
            file=sys.stderr,
            flush=True,
        )
        return None
    sim.program_token_file = token_file.path
    return token_file


def _say_why_the_run_stands_still(lines: list[str]) -> None:
    print("eyesim: the run has not moved on for 3 s of real time:", file=sys.stderr)
    for line in lines:
        print(f"  {line}", file=sys.stderr)
    sys.stderr.flush()


class _WallLimit:
    """--wall-limit: ends the run after that much real time."""

    def __init__(self, sim, seconds: float):
        self.reached = False
        self._timer = threading.Timer(seconds, self._end, args=(sim, seconds))
        self._timer.daemon = True
        self._timer.start()

    def _end(self, sim, seconds: float) -> None:
        self.reached = True
        print(f"eyesim: the wall-clock limit of {seconds:g} s is reached; the run ends", file=sys.stderr, flush=True)
        sim.stop()

    def cancel(self) -> None:
        self._timer.cancel()


class _MemoryTrim:
    """Once a minute of a run, the C heap's free memory goes back to the system
    (platform.return_free_memory): a run of hours, a class's lab session, stays at the size it needs
    instead of growing by the pages freed messages and images leave behind."""

    EVERY = 60.0  # s of wall time

    def __init__(self):
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="memory trim", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while not self._stop.wait(self.EVERY):
            platform.return_free_memory()

    def stop(self) -> None:
        self._stop.set()


def _wall_limit(sim, seconds: float | None) -> _WallLimit | None:
    return None if seconds is None else _WallLimit(sim, seconds)


def scene_workspace(sim, launcher, args):
    """The viewer's scene browser and editor over the scene roots: the current folder, the
    examples and the bundled scenes (read-only), and every --scenes folder."""
    from pathlib import Path

    from eyesim.paths import EXAMPLES_DIR
    from eyesim.scene.builtins import SCENES_DIR
    from eyesim.web.scene_files import SceneRoots
    from eyesim.web.scene_workspace import SceneWorkspace

    folders = [
        ("current folder", Path.cwd(), True),
        ("examples", EXAMPLES_DIR, False),
        ("bundled scenes", SCENES_DIR, False),
    ]
    for folder in args.scenes:
        if not Path(folder).is_dir():
            raise UsageError(f"--scenes {folder}: no such folder")
        folders.append((folder, Path(folder), True))
    workspace = SceneWorkspace(sim, launcher, SceneRoots(folders))
    workspace.browse_at_start = args.scene is None and not args.program
    if args.scene is not None:  # the file this run started with, not the bundled arena it falls back on
        workspace.recent.note(Path(sim.scene.source))
    return workspace


def start_recorders(sim, args) -> list:
    """One recorder per --record file: MCAP for .mcap, the trajectory CSV for anything else."""
    if not args.record and args.record_rate is None:
        return []  # and MCAP is not even imported (start-up time)
    from eyesim.record import Recorder, TrajectoryRecorder
    from eyesim.record.mcap_recorder import DEFAULT_POSE_RATE

    if args.record_rate is not None and not any(p.lower().endswith(".mcap") for p in args.record):
        raise UsageError("--record-rate applies to .mcap recordings: add --record FILE.mcap")
    recorders: list[Recorder | TrajectoryRecorder] = []
    try:
        for path in args.record:
            if path.lower().endswith(".mcap"):
                rate = DEFAULT_POSE_RATE if args.record_rate is None else args.record_rate
                recorders.append(Recorder(sim, path, pose_rate=rate))
            else:
                recorders.append(TrajectoryRecorder(path))
                sim.step_observers.append(recorders[-1])
    except (ValueError, OSError) as error:
        for recorder in recorders:
            recorder.close()
        if isinstance(error, ValueError):
            raise UsageError(f"--record-rate: {error}") from None
        raise UsageError(f"--record: cannot write {error.filename}: {error.strerror}") from None
    return recorders
