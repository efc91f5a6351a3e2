"""The Simulation: owns the scene, the physics world, the robots, the clock and the step loop.

One simulation thread runs `run()`: round after round, the run's schedule (core/schedules.py:
realtime or lock-step, chosen once) waits on the program sockets, has requests carried out
(core/requests.py) and steps physics; each step updates the components, completes pending replies
and tells the step observers; snapshots are published to listeners (DESIGN.md principle 5).
Other threads talk to the simulation only through `call`, which queues work for that thread.

Every answered call that reaches the robot's hardware or the world takes the call time
(DEFAULT_CALL_TIME_US, the scene's CALLTIME, `--call-time`) of simulation time, in both modes:
deterministic mode adds it to the program's clock, realtime mode holds the reply back until
simulation time has gone on by that much since the request came in. What the EyeBot does itself
(LCD drawing, reading the clock) costs only its own few microseconds (protocol.json's cost classes)."""

from __future__ import annotations

import gc
import heapq
import itertools
import logging
import queue
import time
import traceback

from eyesim.core.clock import DEFAULT_CALL_TIME_US, Clock
from eyesim.core.events import EventBus
from eyesim.core.requests import Requests
from eyesim.core.schedules import SNAPSHOT_PERIOD, schedule_for
from eyesim.net.program_server import SimulationEventLoop
from eyesim.net.session import Session
from eyesim.protocol.ops import DEVICE
from eyesim.robot.component import Component
from eyesim.scene.description import Scene
from eyesim.world.builder import build_world

log = logging.getLogger("eyesim")

DEFAULT_STEP_US = 2000  # physics step: 2 ms
TICK_US = 10000  # components' periodic work (Component.tick) runs every 10 ms, RoBIOS's timer rate


class Simulation:
    def __init__(self, scene: Scene, clock: Clock | None = None, step_us: int = DEFAULT_STEP_US):
        self.scene = scene
        self.clock = clock or Clock()
        self.step_us = step_us
        self.events = EventBus()
        self.inbox: queue.SimpleQueue = queue.SimpleQueue()  # actions from other threads
        self.requests = Requests(self)
        self.timing = schedule_for(self)  # realtime or lock-step, for the life of the clock
        # Program sockets are served on this thread: waiting for the next step means waiting on them.
        self.network = SimulationEventLoop(self.requests.deliver, self.requests.connected, self.requests.drop)
        self._running = False
        self.sessions: list[Session] = []
        self.expected_programs: set[int] = set()  # robot ids whose launched program has not connected
        # Process ids of programs whose connection has closed: they are exiting, and the end of a
        # run gives them a moment to do so before stopping them (programs/launcher.py).
        self.disconnected_pids: set[int] = set()
        # The run's program token (net/program_token.py), which every HELLO must carry; None: any
        # program may connect (no program port, or --no-token on loopback). Set before the run starts.
        self.program_token: str | None = None
        self.program_token_file = None  # the Path programs started by hand read it from, if written
        self.stop_when_programs_done = False  # end the run once no program is connected or expected
        self.time_us = 0
        self.steps = 0
        self._scheduled: list = []  # heap of (time_us, seq, action) run at step boundaries
        self._sequence = itertools.count()
        self.stopping = False
        self.until_us: int | None = None  # where the run under way ends (run's `until`)
        self._pause_at_us: int | None = None  # step_for: pause again once simulation time gets here
        self._last_snapshot = 0.0
        self._publish_again = False  # every component publishes its state at the next tick
        self.step_observers: list = []  # called as observer(sim) after every physics step
        # called as observer(robot, request, reply) after a request was answered at once (recorders)
        self.request_observers: list = []
        # Launched programs' output by process id: deterministic mode passes on what a program wrote
        # before each of its calls, unfinished lines too (programs/program_output.py).
        self.program_outputs: dict = {}
        self._build()

    # -- building ------------------------------------------------------------------------------
    def _build(self, built=None) -> None:
        built = built or build_world(self.scene, self.step_us / 1e6)
        call_time_ms = self.scene.settings.call_time
        self.call_time_us = DEFAULT_CALL_TIME_US if call_time_ms is None else round(call_time_ms * 1000)
        self.world, self.floor, self.water = built.world, built.floor, built.water
        self.robots, self.objects, self.floating = built.robots, built.objects, built.floating
        # Only components that do something around a step are called every step (100 robots
        # have hundreds of components; most only answer queries).
        components = [c for robot in self.robots for c in robot.components]
        self._before_step = [c.before_step for c in components if type(c).before_step is not Component.before_step]
        self._after_step = [c.after_step for c in components if type(c).after_step is not Component.after_step]
        self._tick = [c.tick for c in components if type(c).tick is not Component.tick]
        self._tick_steps = max(1, round(TICK_US / self.step_us))
        self._publishers = [
            (robot.id, c) for robot in self.robots for c in robot.components if type(c).publish is not Component.publish
        ]
        for robot in self.robots:
            for component in robot.components:
                component.reset()

    def reset(self) -> None:
        """Back to the scene's initial state; connected programs stay connected."""
        self.world.reset()
        for robot in self.robots:
            for component in robot.components:
                component.reset()
        self.events.reset()

    def replace_scene(self, scene: Scene, opened: bool = True) -> None:
        """Put another scene in place of this one (the viewer's scene browser and editor), on the
        simulation thread: connected programs are disconnected (their robots are gone), the world
        is built afresh and simulation time goes on. A scene the physics cannot build raises and
        leaves the old one running. `opened`: another scene (a file opened, a new one), not an edit
        of this one (listeners such as recorders tell the two apart)."""
        built = build_world(scene, self.step_us / 1e6)  # first: a failure changes nothing
        self.shutdown_programs()
        self.scene = scene
        self._build(built)
        if gc.get_freeze_count():  # the run froze what it set up (app/simulate.py): the old scene
            gc.unfreeze()  # holds cycles (robots and their parts) only a collection frees, so collect
            gc.collect()  # it once, then freeze the new scene for the rest of the run
            gc.freeze()
        self._publish_again = True  # the new robots' LCD and camera images, whether they change or not
        self.events.emit({"type": "new-scene", "opened": opened})

    def shutdown_programs(self) -> None:
        """Disconnect every program, keeping the port open for new ones (a new scene, the run's end)."""
        self.requests.disconnect_all()

    @property
    def time(self) -> float:
        return self.time_us / 1e6

    def robot_by_id(self, robot_id: int):
        return self.robots[robot_id - 1] if 1 <= robot_id <= len(self.robots) else None

    def object_by_id(self, object_id: int):
        return self.objects[object_id - 1] if 1 <= object_id <= len(self.objects) else None

    # -- entry points for other threads ---------------------------------------------------------
    def call(self, action) -> None:
        """Run `action(sim)` on the simulation thread (browser commands, launcher notices)."""
        self.inbox.put(action)
        self.network.wake()

    def on_loop(self, action) -> None:
        """Run `action(sim)` on the simulation thread, or at once while no loop runs (setting up and
        tearing down, before `run` starts and after it ended)."""
        if self._running:
            self.call(action)
        else:
            action(self)

    def stop(self) -> None:
        self.stopping = True
        self.network.wake()

    def step_for(self, duration_us: int) -> None:
        """The viewer's Step: let simulation time go on as it does running, by `duration_us` rounded
        up to whole physics steps (at least one), then pause (running, it pauses after that long).
        On the simulation thread."""
        steps = max(1, -(-duration_us // self.step_us))
        self._pause_at_us = self.time_us + steps * self.step_us
        self.clock.set_paused(False, self.time_us)

    # -- things that happen at a simulation time ------------------------------------------------
    def schedule(self, time_us: int, action) -> None:
        """Run `action(sim)` at the first step boundary at or after `time_us` (scripted input)."""
        heapq.heappush(self._scheduled, (time_us, next(self._sequence), action))

    # -- the loop --------------------------------------------------------------------------------
    def run(self, until: float | None = None) -> None:
        """Run until `stop()` or until simulation time reaches `until` seconds."""
        until_us = self.until_us = None if until is None else round(until * 1e6)
        self.clock.anchor(self.time_us)
        self._running = True
        one_round = self.timing.round
        try:
            while not self.stopping and (until_us is None or self.time_us < until_us):
                one_round()
                if self.events.listeners:
                    self._publish()
        finally:
            self._running = False
            self.handle_queued()  # actions queued while the loop was ending, e.g. a listener to remove
            self._publish(force=True)

    def wait(self, timeout: float) -> None:
        """Wait up to `timeout` s for program sockets or other threads, then take what arrived."""
        self.network.poll(timeout)
        self.handle_queued()

    def handle_queued(self) -> None:
        """Carry out what other threads queued, on the simulation thread; also after the loop ended
        (the last console lines, program exits), so observers such as recorders see them."""
        while not self.inbox.empty():
            action = self.inbox.get_nowait()
            try:
                action(self)
            except Exception:
                log.error("command failed:\n%s", traceback.format_exc())
            self.requests.wake_pending()

    def step(self) -> None:
        """One physics step with its three phases."""
        while self._scheduled and self._scheduled[0][0] <= self.time_us:
            _, _, action = heapq.heappop(self._scheduled)
            action(self)
        dt = self.step_us / 1e6
        for before_step in self._before_step:
            before_step(dt)
        for forces in self.floating:
            forces.apply()
        self.world.step()
        self.time_us += self.step_us
        self.steps += 1
        for after_step in self._after_step:
            after_step(dt)
        if self.steps % self._tick_steps == 0:
            tick_dt = self._tick_steps * self.step_us / 1e6
            for tick in self._tick:
                tick(tick_dt)
        if self.sessions:
            self.requests.wake_pending()
        for observer in self.step_observers:
            observer(self)
        if self._pause_at_us is not None and self.time_us >= self._pause_at_us:
            self._pause_at_us = None
            self.clock.set_paused(True, self.time_us)

    def call_cost_us(self, op) -> int:
        """Simulation time an answered call takes, by the op's cost class (protocol.json, docs/
        protocol.md#what-a-call-costs): a call that reaches the robot's hardware or the world takes
        the call time, or its own cost when that is larger (camera images); what the EyeBot does
        itself (LCD, the clock) only its own few microseconds; blocking calls only what they wait
        (OSWait(n) exactly n ms), so waits and timers stay exact."""
        if op.cost == DEVICE:
            return max(op.cost_us, self.call_time_us)
        return op.cost_us

    # -- programs coming and going ----------------------------------------------------------------
    def drop_session(self, session: Session) -> None:
        """A program's connection ended (or is ended): forget it; the run may be over."""
        self.requests.drop(session)

    def program_gone(self, robot_id: int) -> None:
        """A launched program exited; if it never connected, stop waiting for it."""
        self.expected_programs.discard(robot_id)
        self.check_programs_done()

    def check_programs_done(self) -> None:
        # Decided here, on the simulation thread, when a session closes: in deterministic mode
        # time cannot have moved since the program's last call, so the run ends at the same
        # simulation time every time.
        if (
            self.stop_when_programs_done
            and not self.expected_programs
            and not any(s.robot is not None for s in self.sessions)
        ):
            self.stop()

    def close(self) -> None:
        """Let go of the program sockets and the selector's descriptors (a simulation that is thrown
        away, such as the robot editor's previews, does not hold them until garbage collection).
        The world stays readable; the loop cannot run again."""
        self.shutdown_programs()
        self.network.close()

    # -- publishing ------------------------------------------------------------------------------
    def _publish(self, force: bool = False) -> None:
        if not self.events.listeners:
            return
        now = time.perf_counter()
        if not force and now - self._last_snapshot < SNAPSHOT_PERIOD:
            return
        self._last_snapshot = now
        if self.events.wants_lcd:  # LCD and camera images: only while someone shows them
            again, self._publish_again = self._publish_again, False
            for robot_id, component in self._publishers:
                component.publish(robot_id, self.events, again)
        self.events.snapshot(self)

    def republish_lcd(self) -> None:
        """Send every robot's LCD and camera image again at the next publish tick (a browser has
        just connected)."""
        self._publish_again = True
