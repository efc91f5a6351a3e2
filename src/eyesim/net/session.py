"""A connected program: its connection, the robot it drives and its place in simulated time."""

from __future__ import annotations

import logging
from collections import deque
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Callable, Protocol

from eyesim.protocol import generated as g
from eyesim.protocol.ops import OpSpec

if TYPE_CHECKING:
    from eyesim.robot.robot import Robot

log = logging.getLogger("eyesim")
BUSY_WAIT_GRACE = 0.5  # s of wall time; see Session.blocked
TIMER_LOCKING = (g.OP_TIMER_ATTACH, g.OP_TIMER_DETACH)  # see Session.timers_locked


class Connection(Protocol):
    """What the engine needs from a transport, on the simulation thread."""

    def send(self, data: bytes) -> None: ...

    def close(self, flush: bool = False) -> None:
        """Close the connection; with `flush`, first send what is queued for it."""

    def resume(self) -> None:
        """A queued request was taken: there may be room to read more."""


@dataclass(slots=True)
class Request:
    """A decoded request waiting for, or being handled by, the simulation thread."""

    session: "Session"
    op: OpSpec
    request_id: int
    args: tuple
    time_us: int = 0  # simulation time at which it is handled
    by_timer: bool = False  # deterministic: made by the library's timer thread (see Session.enqueue)


class Pending:
    """A reply that comes later (DESIGN.md: blocking calls never block the simulation thread).

    `poll(at_us)` returns the reply values once the condition holds at simulation time `at_us`,
    else None. `wake_us` is set for purely time-based waits (OSWait), so deterministic mode can
    resume them between physics steps, at exactly the time asked for. A `background` wait is made
    by a helper thread of the library (the timer thread), not by the program's own logic (see
    Session.blocked)."""

    background = False

    def __init__(self, poll: Callable[[int], tuple | None], wake_us: int | None = None):
        self.poll = poll
        self.wake_us = wake_us

    @classmethod
    def until(cls, wake_us: int, reply: tuple) -> "Pending":
        return cls(lambda at_us: reply if at_us >= wake_us else None, wake_us)

    def cancel(self) -> None:
        """The call will not be answered (its program is gone)."""


class Deferred(Pending):
    """An ordinary call whose reply is made off the simulation thread (a camera image, drawn on the
    render thread): `work` is a physics.render_worker.Frame whose result is (reply values, encoded
    reply frame). It takes its cost in simulation time like a call answered at once: the engine
    sets `wake_us` to when its reply is due, and the work wakes the engine when it is done. The
    reply leaves once both hold; in deterministic mode the simulation waits for the work at
    that time, so the reply comes at the same simulation time in every run. `answered()` runs on
    the simulation thread when it leaves."""

    wake_us: int  # 0 until the engine sets it (Schedule.defer)

    def __init__(self, work, answered: Callable[[], None] = lambda: None):
        # not Pending.__init__: a bound method kept on the instance would make a reference cycle,
        # and the frame's megabytes would wait for the garbage collector
        self.wake_us = 0
        self.work = work
        self.answered = answered

    def poll(self, at_us: int) -> tuple | None:
        if at_us < self.wake_us or not self.work.done():
            return None
        return self.work.result[0] if self.work.error is None else ()

    def cancel(self) -> None:
        self.work.cancel()


@dataclass(eq=False)  # a session is itself: compared field by field, each `in sim.sessions` compared whole sessions
class Session:
    connection: Connection
    peer: str = ""
    robot: Robot | None = None  # once the handshake bound one
    program: str = ""
    pid: int = 0
    local_time_us: int = 0  # the program's own clock in deterministic mode
    queued: deque = field(default_factory=deque)  # requests waiting for their turn (deterministic)
    pending: list = field(default_factory=list)  # (Request, Pending) answered later
    closed: bool = False
    helper_threads: int = 0  # library threads that make calls too: 1 once the program uses timers
    threads_seen: int = 1  # threads of the program seen making calls at once (see note_request)
    last_request_wall: float = 0.0  # wall-clock time (perf_counter) of the latest request
    free_running: bool = False  # time goes on while its main thread busy-waits (see blocked)
    in_turn: bool = False  # realtime: in the engine's round of programs to serve
    replies_held: int = 0  # realtime: replies waiting for their call time to pass
    last_clock_ms: int = -1  # deterministic: what its last clock read (OSGetCount, OSGetTime) returned
    # Deterministic timers (see enqueue): the timer thread's first wait is still to come; it runs
    # callbacks (its wait was answered); the calls those callbacks made, served before any other.
    timer_starting: bool = False
    timer_running: bool = False
    timer_queued: deque = field(default_factory=deque)

    def enqueue(self, request: Request) -> None:
        """Deterministic: queue a request so that timer callbacks run at their simulation time in
        the same order with the main thread's calls in every run. While the timer thread runs
        callbacks, every other thread of the program waits in a call whose reply is held (see
        held), so whatever arrives then comes from a callback and is served first. The timer
        thread's first wait goes ahead of anything the main thread sent since it attached the
        timer, however the operating system started the thread."""
        if self.timer_running:
            request.by_timer = True
            self.timer_queued.append(request)
        elif self.timer_starting and request.op.code == g.OP_TIMER_WAIT:
            self.timer_starting = False
            request.by_timer = True
            self.queued.appendleft(request)
        else:
            self.queued.append(request)

    def next_queue(self) -> deque:
        """The queue whose requests are served next: the timer callbacks' while they run."""
        return self.timer_queued if self.timer_running else self.queued

    def held(self, request: Request) -> bool:
        """Deterministic: is the reply to this waiting call held back? The main thread's are, while
        timer callbacks run (they run alone, as on the robot)."""
        return self.timer_running and not request.by_timer

    def timers_locked(self) -> bool:
        """Deterministic: the main thread waits in OSAttachTimer or OSDetachTimer, which hold the
        library's timer lock, so no callback can run before that call is answered."""
        return any(request.op.code in TIMER_LOCKING for request in self.queued)

    def note_request(self, now_wall: float) -> None:
        self.last_request_wall = now_wall
        # A thread of the library's calls one at a time: a request while others wait in blocking
        # calls comes from yet another thread.
        self.threads_seen = max(self.threads_seen, len(self.pending) + 1)
        if self.pending:
            self.free_running = False  # another thread waits, so a computing one made this call

    def woke(self, now_wall: float) -> None:
        """A thread's blocking call was answered: it goes on (or ends), so time waits for it again,
        with a fresh grace, instead of running on for a thread that stopped calling earlier."""
        self.free_running = False
        self.last_request_wall = now_wall

    def computing(self, now_wall: float) -> bool:
        """Deterministic: must the run wait for this program's next request before going on?"""
        if self.timer_starting:  # wait for the timer thread's first wait (see enqueue)
            if now_wall - self.last_request_wall <= BUSY_WAIT_GRACE:
                return True
            self.timer_starting = False
            self.last_request_wall = now_wall  # the busy-wait grace (blocked) starts now, not at the last call
            log.warning("%s: the library's timer thread made no call; timers will not run", self.name)
        return not self.next_queue() and not self.blocked(now_wall)

    def blocked(self, now_wall: float) -> bool:
        """Deterministic mode: may simulation time go on before this program's next request?

        Only while every thread of the program that makes calls waits in one (OSWait, KEYGet, ...):
        the main thread, the others seen calling, and, once it uses timers, the library's timer thread. Time stands still
        while the main thread computes and while timer callbacks run. One exception keeps a main
        thread that busy-waits for a timer callback from hanging: after BUSY_WAIT_GRACE seconds of
        wall time without a request, time goes on without it (no longer bit-identical) until the
        main thread makes a call again. The program's own threads count the same way: once one
        called while another waited (a thread waiting in KEYGet beside a VW control loop), time
        goes on only while all of them wait, so the loop sees the time it would alone."""
        others = max(self.threads_seen - 1, self.helper_threads)
        if len(self.pending) > others:
            return True
        if not others:
            return False
        if not self.free_running and now_wall - self.last_request_wall > BUSY_WAIT_GRACE:
            self.free_running = True
            log.warning(
                "%s makes no RoBIOS call while its other threads wait; simulation time goes on without it "
                "(the run is no longer deterministic)",
                self.name,
            )
        return self.free_running

    @property
    def name(self) -> str:
        robot = f"robot {self.robot.id}" if self.robot is not None else "no robot"
        program = self.program if len(self.program) <= 100 else self.program[:97] + "..."  # for log lines
        return f"{program or 'program'} ({robot}, {self.peer})"
