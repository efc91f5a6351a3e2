"""The Simulation: owns the scene, the physics world, the robots, the clock and the request queue.

One simulation thread runs `run()`: it applies queued requests and commands, steps physics, updates
sensors, completes pending replies and publishes snapshots (DESIGN.md principle 5). Other threads
talk to it only through `submit`/`call`, which enqueue work.

Deterministic mode is a conservative lock-step: every connected program has its own clock
(`Session.local_time_us`). Each request is handled at its program's time and advances that time by
the operation's documented cost; physics only steps once every program is either blocked in a
pending call or has asked for something at or beyond the next step. Requests are taken in order
of (time, robot id), so the result does not depend on how the OS schedules the programs.

Every answered call that reaches the robot's hardware or the world takes the call time
(DEFAULT_CALL_TIME_US, the scene's CALLTIME, `--call-time`) of simulation time, in both modes:
deterministic mode adds it to the program's clock, realtime mode holds the reply back until
simulation time has gone on by that much since the request came in. What the EyeBot does itself
(LCD drawing, reading the clock) costs only its own few microseconds (protocol.json's cost classes)."""

from __future__ import annotations

import heapq
import itertools
import logging
import queue
import reprlib
import secrets
import struct
import time
import traceback
from collections import deque

from eyesim import commands
from eyesim.core.clock import Clock
from eyesim.core.events import EventBus
from eyesim.net import program_token
from eyesim.net.program_server import ProgramSockets, version_refusal
from eyesim.net.session import Deferred, Pending, Request, Session
from eyesim.protocol import encode_error, encode_message, generated as g
from eyesim.protocol.ops import DEVICE, LOCAL
from eyesim.robot.component import Component
from eyesim.scene.description import Scene
from eyesim.world.builder import build_world

log = logging.getLogger("eyesim")

DEFAULT_STEP_US = 2000  # physics step: 2 ms
TICK_US = 10000  # components' periodic work (Component.tick) runs every 10 ms, RoBIOS's timer rate
SNAPSHOT_PERIOD = 1 / 30  # wall seconds between published snapshots
MAX_CATCH_UP_STEPS = 50  # realtime: steps taken in one go before looking at the queue again
IDLE_WAIT = 0.05  # s the loop sleeps when nothing can happen (paused, waiting for programs)
IDLE_POLL_STEPS = 50  # at --speed max with no program connected: look for new connections this often
QUIET_STEPS = 50  # deterministic: steps taken in one go while every program waits (then look at the sockets)
# Simulation time an ordinary call takes (docs/running.md#call-time): EyeSim answered in a few ms,
# and lab programs that count loop iterations instead of time were written against that.
DEFAULT_CALL_TIME_US = 4000


class Simulation:
    def __init__(self, scene: Scene, clock: Clock | None = None, step_us: int = DEFAULT_STEP_US):
        self.scene = scene
        self.clock = clock or Clock()
        self.step_us = step_us
        self.events = EventBus()
        self.inbox: queue.SimpleQueue = queue.SimpleQueue()  # actions from other threads
        # Program sockets are served on this thread: waiting for the next step means waiting on them.
        self.network = ProgramSockets(self._deliver, self._connected, self.drop_session)
        self._ready: deque[Session] = deque()  # realtime: programs with queued requests, served in turn
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
        self._stopping = False
        self._until_us: int | None = None  # where the run under way ends (run's `until`)
        self._answered_later = 0  # pending calls answered so far (a step that answers one ends a quiet stretch)
        self._pause_at_us: int | None = None  # step_for: pause again once simulation time gets here
        self._last_snapshot = 0.0
        self._publish_again = False  # every component publishes its state at the next tick
        self.step_observers: list = []  # called as observer(sim) after every physics step
        call_time_ms = scene.settings.call_time
        self.call_time_us = DEFAULT_CALL_TIME_US if call_time_ms is None else round(call_time_ms * 1000)
        self._held: list = []  # realtime: heap of (due_us, seq, session, frame), replies held for the call time
        # called as observer(robot, request, reply) after a request was answered at once (recorders)
        self.request_observers: list = []
        # Launched programs' output by process id: deterministic mode passes on what a program wrote
        # before each of its calls, unfinished lines too (programs/program_output.py).
        self.program_outputs: dict = {}
        self._build()

    # -- building ------------------------------------------------------------------------------
    def _build(self, built=None) -> None:
        built = built or build_world(self.scene, self.step_us / 1e6)
        self.world, self.floor, self.water = built.world, built.floor, built.water
        self.robots, self.objects, self.floating = built.robots, built.objects, built.floating
        # Only components that do something around a step are called every step (100 robots
        # have hundreds of components; most only answer queries).
        components = [c for robot in self.robots for c in robot.components]
        self._before_step = [c.before_step for c in components if type(c).before_step is not Component.before_step]
        self._after_step = [c.after_step for c in components if type(c).after_step is not Component.after_step]
        self._tick = [c.tick for c in components if type(c).tick is not Component.tick]
        self._tick_steps = max(1, round(TICK_US / self.step_us))
        self._publishers = [(robot.id, c) for robot in self.robots for c in robot.components
                            if type(c).publish is not Component.publish]
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
        call_time_ms = scene.settings.call_time
        self.call_time_us = DEFAULT_CALL_TIME_US if call_time_ms is None else round(call_time_ms * 1000)
        self._build(built)
        self._publish_again = True  # the new robots' LCD and camera images, whether they change or not
        self.events.emit({"type": "new-scene", "opened": opened})

    def shutdown_programs(self) -> None:
        """Disconnect every program, keeping the port open for new ones."""
        for session in list(self.sessions):
            session.connection.close()
            self.drop_session(session)
        self.expected_programs.clear()
        self._ready.clear()
        self._held.clear()

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
        self._stopping = True
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
        until_us = self._until_us = None if until is None else round(until * 1e6)
        self.clock.anchor(self.time_us)
        self._running = True
        one_round = self._deterministic_round if self.clock.deterministic else self._realtime_round
        try:
            while not self._stopping and (until_us is None or self.time_us < until_us):
                one_round()
                if self.events.listeners:
                    self._publish()
        finally:
            self._running = False
            self._drain_inbox()  # actions queued while the loop was ending, e.g. a listener to remove
            self._publish(force=True)

    def handle_queued(self) -> None:
        """Handle what is still queued after the loop ended (the last console lines, program exits),
        so observers such as recorders see them."""
        self._drain_inbox()

    def _realtime_round(self) -> None:
        if self.clock.paused:  # calls are carried out; held replies wait: their time does not go on
            self._wait(0 if self._ready else IDLE_WAIT)
            self._serve()
            return
        if self.clock.as_fast_as_possible:  # one step per round, each program served once in between
            if self.sessions or self.steps % IDLE_POLL_STEPS == 0:
                self._wait(0)
            elif not self.inbox.empty():  # no program connected: a new connection can wait a little
                self._drain_inbox()
            if self._ready:
                self._serve(rounds=1)
            self.step()
            if self._held:
                self._release_held()
            return
        self._release_held()
        wait = self.clock.seconds_until(self.time_us + self.step_us)
        if wait > 0:
            step_due = time.perf_counter() + wait
            if self._ready:  # serve in turn until the step is due, then look at the sockets again
                self._serve(deadline=step_due)
                self._wait(0)
                return
            if self._held:  # due by now (it was not a moment ago): 0, just look at the sockets
                wait = max(0.0, min(wait, self.clock.seconds_until(self._held[0][0])))
            self._wait(min(wait, SNAPSHOT_PERIOD))
            if self._ready:  # what arrived is served now, not a round later
                self._serve(deadline=step_due)
            return
        self._wait(0)
        for _ in range(MAX_CATCH_UP_STEPS):
            self.step()
            if self.clock.seconds_until(self.time_us + self.step_us) > 0:
                break
        if self.clock.seconds_until(self.time_us) < -0.25:
            self.clock.anchor(self.time_us)  # too far behind (slow machine): don't try to catch up

    def _wait(self, timeout: float) -> None:
        """Wait up to `timeout` s for program sockets or other threads, then take what arrived."""
        self.network.poll(timeout)
        self._drain_inbox()

    def _drain_inbox(self) -> None:
        while not self.inbox.empty():
            action = self.inbox.get_nowait()
            try:
                action(self)
            except Exception:
                log.error("command failed:\n%s", traceback.format_exc())
            self._wake_pending()

    # -- program connections (called by self.network on this thread) ---------------------------------
    def _connected(self, session: Session) -> None:
        session.local_time_us = self.time_us
        self.sessions.append(session)

    def _deliver(self, request: Request) -> None:
        """A request read from a program's socket. Realtime: served in turn with other programs';
        deterministic: queued for its time (see _deterministic_round). The handshake, and anything
        sent before it, is answered at once."""
        session = request.session
        if session.closed:
            return
        if self.clock.deterministic:  # what Session.blocked goes by
            session.note_request(time.perf_counter())
        if request.op.code == g.OP_HELLO or session.robot is None:
            request.time_us = max(self.time_us, session.local_time_us)
            self._execute(request)
            return
        if self.clock.deterministic:
            session.enqueue(request)
        else:
            session.queued.append(request)
            self._take_turn(session)

    def _take_turn(self, session: Session) -> None:
        """Realtime: put the program in the round of programs to serve, if it has a request waiting
        and is not still taking its last call's time (then its held reply's release does this)."""
        if session.queued and not session.in_turn and not session.replies_held:
            session.in_turn = True
            self._ready.append(session)

    def _serve(self, rounds: int | None = None, deadline: float | None = None) -> None:
        """Realtime: carry out queued requests, one program's at a time in turn (a program that
        pipelines requests gets one turn per round like the rest), for `rounds` rounds or until
        the wall clock passes `deadline`, or until none are left."""
        remaining = len(self._ready) * rounds if rounds is not None else None
        while self._ready and remaining != 0:
            session = self._ready.popleft()
            session.in_turn = False
            # Taking a request can decode the next one and put the program back in the round
            # before its reply is held; the release of that reply gives it its next turn.
            if session.closed or session.replies_held:
                continue
            self._take_request(session)
            self._take_turn(session)
            if remaining is not None:
                remaining -= 1
            if deadline is not None and time.perf_counter() >= deadline:
                return

    def _take_request(self, session: Session, at_us: int | None = None) -> None:
        if self.clock.deterministic:
            self._flush_output(session)
        request = session.next_queue().popleft()
        if at_us is None:
            # Realtime: calls answered at once move the program's clock on by their cost within
            # the step under way, never past it (it would run ahead of the simulation).
            at_us = max(self.time_us, min(session.local_time_us, self.time_us + self.step_us))
        request.time_us = at_us
        self._execute(request)
        session.connection.resume()  # room in its queue again, unless the call now waits (pending)

    def _deterministic_round(self) -> None:
        if self.clock.paused:  # nothing goes on; the order of everything is kept for when it does
            self._wait(IDLE_WAIT)
            return
        self._wait(0)
        if self._stopping:  # the last program just ended: not one more step, so every run ends alike
            return
        live = [s for s in self.sessions if s.robot is not None and not s.closed]
        now = time.perf_counter()
        waiting_for = [s for s in live if s.computing(now)]
        if waiting_for or self.expected_programs:
            self._wait(IDLE_WAIT)  # a program is computing: wait for its next call
            return
        boundary = self.time_us + self.step_us
        best = None
        for session in live:
            waiting = [(r, p) for r, p in session.pending if not session.held(r)]
            if session.next_queue() and not any(isinstance(p, Deferred) for _, p in waiting):
                key = (session.local_time_us, session.robot.id)
            else:
                wake = min((p.wake_us for _, p in waiting if p.wake_us is not None), default=None)
                if wake is None:
                    continue
                key = (max(wake, self.time_us), session.robot.id)
            if best is None or key < best[0]:
                best = (key, session)
        if best is None or best[0][0] >= boundary:
            self._step_while_quiet(None if best is None else best[0][0])
            return
        (at_us, _), session = best
        if session.next_queue():
            self._take_request(session, at_us)
        elif not self._wake_session(session, at_us):
            self._wait(IDLE_WAIT)  # its reply is still being made (a camera image): wait for it, not time

    def _step_while_quiet(self, due_us: int | None) -> None:
        """Deterministic: every program waits, for a reply or with a request at `due_us` or later
        (None: no request or timed wait is due). Step until the step that would pass `due_us`, a
        step that answers a waiting call (VWWait done: that program goes on), an action from another
        thread (a viewer command is carried out at the next step boundary), the run's end or
        QUIET_STEPS steps. Meanwhile no program can send anything (each waits for a reply), so
        looking at the sockets between these steps, as every round does, would find nothing."""
        answered = self._answered_later
        for _ in range(QUIET_STEPS):
            self.step()
            if self._answered_later != answered or self._stopping or not self.inbox.empty() or self.clock.paused:
                return
            if due_us is not None and due_us < self.time_us + self.step_us:
                return
            if self._until_us is not None and self.time_us >= self._until_us:
                return

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
            self._wake_pending()
        for observer in self.step_observers:
            observer(self)
        if self._pause_at_us is not None and self.time_us >= self._pause_at_us:
            self._pause_at_us = None
            self.clock.set_paused(True, self.time_us)

    # -- requests --------------------------------------------------------------------------------
    def _execute(self, request: Request) -> None:
        session = request.session
        op = request.op
        try:
            if op.code == g.OP_HELLO:
                result = self._hello(request)
            elif op.code == g.OP_THREADS and session.robot is not None:
                result = self._threads(session)
            elif session.robot is None:
                raise commands.CommandError("the first request must be the HELLO handshake", g.ERR_NO_HANDSHAKE)
            else:
                problem = op.ranges and op.out_of_range(request.args)  # protocol.json's ranges, before any work
                if problem:
                    raise commands.CommandError(problem, g.ERR_BAD_ARGUMENT)
                result = commands.HANDLERS[op.code](self, session.robot, request)
        except commands.CommandError as error:
            self._answer(request, encode_error(op.code, request.request_id, error.code, str(error)))
            if error.code == g.ERR_BAD_TOKEN:  # no second guess on this connection
                session.connection.close(flush=True)
            return
        except Exception:  # a fault stays with its call: the program gets an error, everyone else goes on
            log.error("handler for %s from %s failed:\n%s", op.name, session.name, traceback.format_exc())
            self._answer(request, encode_error(op.code, request.request_id, g.ERR_BAD_ARGUMENT,
                                               "internal simulator error (see the simulator log)"))
            return
        if isinstance(result, Deferred):
            self._defer(request, result)
            return
        if isinstance(result, Pending):
            session.pending.append((request, result))
            session.local_time_us = request.time_us
            if result.background and session.timer_running:  # the callbacks are done: the rest goes on
                session.timer_running = False
                self._wake_session(session, self.time_us)
            return
        self._answer(request, self._reply_frame(request, result))
        for observer in self.request_observers:
            observer(session.robot, request, result)

    def _reply_frame(self, request: Request, values: tuple) -> bytes:
        """The encoded reply; a value that does not fit its field becomes an error reply, never a
        failure of the simulation thread."""
        try:
            return encode_message(request.op.code, g.KIND_REPLY, request.request_id, values)
        except (struct.error, OverflowError, TypeError, ValueError) as error:
            log.error("reply to %s from %s does not encode (%s): %r", request.op.name, request.session.name,
                      error, values)
            return encode_error(request.op.code, request.request_id, g.ERR_BAD_ARGUMENT,
                                "the result does not fit the reply (a value out of range)")

    def call_cost_us(self, op) -> int:
        """Simulation time an answered call takes, by the op's cost class (protocol.json, docs/
        protocol.md#what-a-call-costs): a call that reaches the robot's hardware or the world takes
        the call time, or its own cost when that is larger (camera images); what the EyeBot does
        itself (LCD, the clock) only its own few microseconds; blocking calls only what they wait
        (OSWait(n) exactly n ms), so waits and timers stay exact."""
        if op.cost == DEVICE:
            return max(op.cost_us, self.call_time_us)
        return op.cost_us

    def _answer(self, request: Request, frame: bytes) -> None:
        """Send the reply to a call answered at once, after the call's cost in simulation time."""
        session = request.session
        cost = self.call_cost_us(request.op)
        if self.clock.deterministic or not self.call_time_us or cost == 0 or request.op.cost == LOCAL:
            # Deterministic: the program's clock goes on. Realtime: a local call's few µs (or any call
            # without a call time) move it on within the step under way (_take_request), nothing is held.
            session.local_time_us = request.time_us + cost
            self._send(session, frame)
            return
        # Realtime: the reply leaves once simulation time has gone on by the cost since the request.
        due = max(self._realtime_now_us(), request.time_us) + cost
        session.local_time_us = due  # the program's next call cannot be earlier
        session.replies_held += 1  # its next request waits for this reply, as the program itself would
        heapq.heappush(self._held, (due, next(self._sequence), session, frame))

    def _defer(self, request: Request, deferred: Deferred) -> None:
        """A call answered like any other (see _answer) whose reply is made on another thread: it
        leaves at the same simulation time as _answer's would, or when it is made if that is later
        (deterministic mode waits for it: see _deterministic_round). The program's next request
        waits for the reply, as it would for a held one: one image at a time per program, however
        many it pipelines."""
        session = request.session
        cost = self.call_cost_us(request.op)
        if self.clock.deterministic:
            deferred.wake_us = request.time_us + cost
            session.local_time_us = request.time_us
        else:
            if not self.call_time_us or cost == 0:
                deferred.wake_us = 0  # as soon as it is made
                session.local_time_us = request.time_us + cost
            else:
                deferred.wake_us = session.local_time_us = max(self._realtime_now_us(), request.time_us) + cost
            session.replies_held += 1
        session.pending.append((request, deferred))
        deferred.work.when_done(lambda: self.call(Simulation._wake_pending))

    def _deferred_frame(self, request: Request, deferred: Deferred) -> bytes:
        """The reply a Deferred made; an error reply if making it failed (logged here, once)."""
        if deferred.work.error is None:
            return deferred.work.result[1]
        log.error("handler for %s from %s failed:\n%s", request.op.name, request.session.name, deferred.work.error)
        return encode_error(request.op.code, request.request_id, g.ERR_BAD_ARGUMENT,
                            "internal simulator error (see the simulator log)")

    def _realtime_now_us(self) -> int:
        """Realtime: simulation time now, between steps: the wall clock's, within the step under way
        (at --speed max and while paused, the time of the last step)."""
        if self.clock.paused or self.clock.as_fast_as_possible:
            return self.time_us
        return int(min(max(self.clock.target_us(), self.time_us), self.time_us + self.step_us))

    def _release_held(self) -> None:
        if not self._held:
            return
        now = self._realtime_now_us()
        while self._held and self._held[0][0] <= now:
            _, _, session, frame = heapq.heappop(self._held)
            session.replies_held -= 1
            self._send(session, frame)
            self._take_turn(session)

    def _hello(self, request: Request) -> tuple:
        version, selector, program, pid, token = request.args
        session = request.session
        if version != g.VERSION:
            raise commands.CommandError(version_refusal(version), g.ERR_VERSION)
        if session.robot is not None:
            raise commands.CommandError("handshake sent twice", g.ERR_BAD_PAYLOAD)
        if self.program_token is not None and not secrets.compare_digest(token.encode(), self.program_token.encode()):
            log.warning("refused a program from %s (%s, pid %d): %s program token", session.peer,
                        reprlib.repr(program), pid, "wrong" if token else "no")
            raise commands.CommandError(program_token.refusal(token, self.program_token_file), g.ERR_BAD_TOKEN)
        robot = self._choose_robot(selector)
        session.robot, session.program, session.pid = robot, program, pid
        session.local_time_us = self.time_us
        self.expected_programs.discard(robot.id)
        log.info("%s connected", session.name)
        return (g.VERSION, robot.id, robot.name)

    def _threads(self, session: Session) -> tuple:
        """The library says a second thread of the program makes calls (THREADS, sent once, before
        that thread's first call): from now on time goes on only while both wait (Session.blocked),
        even if the second thread's first call arrives while the main thread computes."""
        session.threads_seen = max(session.threads_seen, 2)
        if self.clock.deterministic:
            log.warning("robot %d (%s): RoBIOS calls come from more than one thread of the program; their "
                        "order follows the operating system's scheduling, so this deterministic run may not "
                        "repeat exactly (docs/running.md#time)", session.robot.id,
                        session.program or "program")
        return (0,)

    def _choose_robot(self, selector: str):
        taken = {s.robot.id for s in self.sessions if s.robot is not None and not s.closed}
        names = ", ".join(f"{r.id} {r.name}" for r in self.robots) or "none"
        if not self.robots:
            raise commands.CommandError("the scene has no robots", g.ERR_NO_ROBOT)
        if selector == "":
            free = [r for r in self.robots if r.id not in taken]
            if not free:
                raise commands.CommandError(f"every robot already runs a program (robots: {names})", g.ERR_NO_ROBOT)
            return free[0]
        if selector.isascii() and selector.isdigit():  # not '²', which isdigit() but int() refuses
            robot = self.robot_by_id(int(selector)) if len(selector) <= 9 else None
            candidates = [robot] if robot else []
        else:
            candidates = [r for r in self.robots if r.name.lower() == selector.lower()]
        if not candidates:
            raise commands.CommandError(f"no robot {reprlib.repr(selector)} in the scene (robots: {names})",
                                        g.ERR_NO_ROBOT)
        free = [r for r in candidates if r.id not in taken]
        if not free:
            raise commands.CommandError(f"robot {selector!r} already runs a program", g.ERR_NO_ROBOT)
        return free[0]

    def _wake_pending(self) -> None:
        for session in self.sessions:
            if session.pending:
                self._wake_session(session, self.time_us)

    def _wake_session(self, session: Session, at_us: int) -> bool:
        """Complete the session's pending replies whose condition holds at time `at_us`; whether any did.
        Deterministic: the timer thread's wait first; once it is answered, the callbacks run alone
        (the other replies are held, Session.held)."""
        still = []
        for request, pending in sorted(session.pending, key=lambda waiting: not waiting[1].background):
            held = self.clock.deterministic and (session.held(request) or pending.background and session.timers_locked())
            values = None if held else pending.poll(at_us)
            if values is None:
                still.append((request, pending))
                continue
            if pending.background and self.clock.deterministic:
                session.timer_running = True
            session.local_time_us = max(session.local_time_us, at_us)
            if not isinstance(pending, Deferred):
                self._send(session, self._reply_frame(request, values))
                continue
            self._send(session, self._deferred_frame(request, pending))
            pending.answered()
            if not self.clock.deterministic:
                session.replies_held -= 1
                self._take_turn(session)
            if pending.work.error is None:
                for observer in self.request_observers:
                    observer(session.robot, request, values)
        answered = len(still) < len(session.pending)
        session.pending = still
        if answered:
            self._answered_later += 1
            if self.clock.deterministic:
                session.woke(time.perf_counter())
            if not session.closed:
                session.connection.resume()  # room for requests it holds back (program_server.MAX_QUEUED)
        return answered

    def _send(self, session: Session, frame: bytes) -> None:
        if not session.closed:
            session.connection.send(frame)

    def _flush_output(self, session: Session) -> None:
        output = self.program_outputs.get(session.pid) if session.pid else None
        if output is not None:
            output.flush()

    def drop_session(self, session: Session) -> None:
        """A program's connection ended (or is ended): forget it; the run may be over."""
        self._flush_output(session)
        session.closed = True
        for _, pending in session.pending:
            pending.cancel()
        session.pending.clear()
        session.queued.clear()
        session.timer_queued.clear()
        if session in self.sessions:
            self.sessions.remove(session)
            log.info("%s disconnected", session.name)
            if session.pid:
                self.disconnected_pids.add(session.pid)
        self.check_programs_done()

    def program_gone(self, robot_id: int) -> None:
        """A launched program exited; if it never connected, stop waiting for it."""
        self.expected_programs.discard(robot_id)
        self.check_programs_done()

    def check_programs_done(self) -> None:
        # Decided here, on the simulation thread, when a session closes: in deterministic mode
        # time cannot have moved since the program's last call, so the run ends at the same
        # simulation time every time.
        if self.stop_when_programs_done and not self.expected_programs and \
                not any(s.robot is not None for s in self.sessions):
            self.stop()

    def close(self) -> None:
        """Let go of the program sockets and the selector's descriptors (a simulation that is thrown
        away, such as the robot editor's previews, does not hold them until garbage collection).
        The world stays readable; the loop cannot run again."""
        self.shutdown_sessions()
        self.network.close()

    def shutdown_sessions(self) -> None:
        self.network.close_all()
        for session in list(self.sessions):
            session.connection.close()
            self.drop_session(session)

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
