"""The two ways a run's time goes on, chosen once for the clock's mode (`schedule_for`).

`RealtimeSchedule`: simulation time follows the wall clock. Programs with requests waiting are
served in turn, one request each per round, until the next step is due; physics steps are never
postponed for requests. A call answered at once moves its program's clock on by its own cost
within the step under way, never past it; a call that takes the call time is answered once that
much simulation time has passed (its reply is held until then).

`LockstepSchedule` (deterministic mode) is a conservative lock-step: every connected program has
its own clock (`Session.local_time_us`). Each request is handled at its program's time and
advances that time by the operation's cost; physics only steps once every program is either
blocked in a pending call or has asked for something at or beyond the next step. Requests are
taken in order of (time, robot id), so the result does not depend on how the OS schedules the
programs.

Both answer to the same calls from the loop (`round`) and from request handling (core/requests.py:
`arrived`, `queue`, `answer`, `defer`, `holds`, `answered`, `woke`, `several_threads`, `clear`)."""

from __future__ import annotations

import heapq
import itertools
import logging
import time
from collections import deque

from eyesim.net.session import Deferred, Request, Session
from eyesim.protocol.ops import LOCAL

log = logging.getLogger("eyesim")

MAX_CATCH_UP_STEPS = 50  # realtime: steps taken in one go before looking at the queue again
IDLE_WAIT = 0.05  # s the loop sleeps when nothing can happen (paused, waiting for programs)
IDLE_POLL_STEPS = 50  # at --speed max with no program connected: look for new connections this often
QUIET_STEPS = 50  # deterministic: steps taken in one go while every program waits (then look at the sockets)
SNAPSHOT_PERIOD = 1 / 30  # wall seconds between published snapshots (the longest wait for sockets)


class RealtimeSchedule:
    def __init__(self, sim):
        self.sim = sim
        self.ready: deque[Session] = deque()  # programs with queued requests, served in turn
        self.held: list = []  # heap of (due_us, seq, session, frame), replies held for the call time
        self._sequence = itertools.count()

    def round(self) -> None:
        sim, clock = self.sim, self.sim.clock
        if clock.paused:  # calls are carried out; held replies wait: their time does not go on
            sim.wait(0 if self.ready else IDLE_WAIT)
            self._serve()
            return
        if clock.as_fast_as_possible:  # one step per round, each program served once in between
            if sim.sessions or sim.steps % IDLE_POLL_STEPS == 0:
                sim.wait(0)
            elif not sim.inbox.empty():  # no program connected: a new connection can wait a little
                sim.handle_queued()
            if self.ready:
                self._serve(rounds=1)
            sim.step()
            if self.held:
                self._release_held()
            return
        self._release_held()
        wait = clock.seconds_until(sim.time_us + sim.step_us)
        if wait > 0:
            step_due = time.perf_counter() + wait
            if self.ready:  # serve in turn until the step is due, then look at the sockets again
                self._serve(deadline=step_due)
                sim.wait(0)
                return
            if self.held:  # due by now (it was not a moment ago): 0, just look at the sockets
                wait = max(0.0, min(wait, clock.seconds_until(self.held[0][0])))
            sim.wait(min(wait, SNAPSHOT_PERIOD))
            if self.ready:  # what arrived is served now, not a round later
                self._serve(deadline=step_due)
            return
        sim.wait(0)
        for _ in range(MAX_CATCH_UP_STEPS):
            sim.step()
            if clock.seconds_until(sim.time_us + sim.step_us) > 0:
                break
        if clock.seconds_until(sim.time_us) < -0.25:
            clock.anchor(sim.time_us)  # too far behind (slow machine): don't try to catch up

    def arrived(self, session: Session) -> None:
        """A request came (before it is queued or, the handshake, answered)."""

    def queue(self, request: Request) -> None:
        request.session.queued.append(request)
        self._take_turn(request.session)

    def _take_turn(self, session: Session) -> None:
        """Put the program in the round of programs to serve, if it has a request waiting and is not
        still taking its last call's time (then its held reply's release does this)."""
        if session.queued and not session.in_turn and not session.replies_held:
            session.in_turn = True
            self.ready.append(session)

    def _serve(self, rounds: int | None = None, deadline: float | None = None) -> None:
        """Carry out queued requests, one program's at a time in turn (a program that pipelines
        requests gets one turn per round like the rest), for `rounds` rounds or until the wall clock
        passes `deadline`, or until none are left."""
        sim = self.sim
        remaining = len(self.ready) * rounds if rounds is not None else None
        while self.ready and remaining != 0:
            session = self.ready.popleft()
            session.in_turn = False
            # Taking a request can decode the next one and put the program back in the round
            # before its reply is held; the release of that reply gives it its next turn.
            if session.closed or session.replies_held:
                continue
            # Calls answered at once move the program's clock on by their cost within the step
            # under way, never past it (it would run ahead of the simulation).
            sim.requests.take(session, max(sim.time_us, min(session.local_time_us, sim.time_us + sim.step_us)))
            self._take_turn(session)
            if remaining is not None:
                remaining -= 1
            if deadline is not None and time.perf_counter() >= deadline:
                return

    def answer(self, request: Request, frame: bytes) -> None:
        """Send the reply to a call answered at once once simulation time has gone on by the call's
        cost since the request; a local call's few µs (or any call without a call time) move the
        program's clock on within the step under way, and nothing is held."""
        session, sim = request.session, self.sim
        cost = sim.call_cost_us(request.op)
        if not sim.call_time_us or cost == 0 or request.op.cost == LOCAL:
            session.local_time_us = request.time_us + cost
            sim.requests.send(session, frame)
            return
        due = max(self._now_us(), request.time_us) + cost
        session.local_time_us = due  # the program's next call cannot be earlier
        session.replies_held += 1  # its next request waits for this reply, as the program itself would
        heapq.heappush(self.held, (due, next(self._sequence), session, frame))

    def defer(self, request: Request, deferred: Deferred) -> None:
        """A reply made on another thread leaves when answer's would, or once it is made if that is
        later. The program's next request waits for it, as for a held reply: one image at a time per
        program, however many it pipelines."""
        session, sim = request.session, self.sim
        cost = sim.call_cost_us(request.op)
        if not sim.call_time_us or cost == 0:
            deferred.wake_us = 0  # as soon as it is made
            session.local_time_us = request.time_us + cost
        else:
            deferred.wake_us = session.local_time_us = max(self._now_us(), request.time_us) + cost
        session.replies_held += 1

    def holds(self, session: Session, request: Request, pending) -> bool:
        return False

    def answered(self, session: Session, pending) -> None:
        """A pending call's reply left: a deferred one lets the program's next request in."""
        if isinstance(pending, Deferred):
            session.replies_held -= 1
            self._take_turn(session)

    def woke(self, session: Session) -> None:
        """Some of the program's waiting calls were answered."""

    def several_threads(self, session: Session) -> None:
        """More than one thread of the program calls (the threads' calls come in the order they come)."""

    def clear(self) -> None:
        self.ready.clear()
        self.held.clear()

    def _now_us(self) -> int:
        """Simulation time now, between steps: the wall clock's, within the step under way (at
        --speed max and while paused, the time of the last step)."""
        sim, clock = self.sim, self.sim.clock
        if clock.paused or clock.as_fast_as_possible:
            return sim.time_us
        return int(min(max(clock.target_us(), sim.time_us), sim.time_us + sim.step_us))

    def _release_held(self) -> None:
        if not self.held:
            return
        now = self._now_us()
        while self.held and self.held[0][0] <= now:
            _, _, session, frame = heapq.heappop(self.held)
            session.replies_held -= 1
            self.sim.requests.send(session, frame)
            self._take_turn(session)


class LockstepSchedule:
    def __init__(self, sim):
        self.sim = sim

    def round(self) -> None:
        sim = self.sim
        if sim.clock.paused:  # nothing goes on; the order of everything is kept for when it does
            sim.wait(IDLE_WAIT)
            return
        sim.wait(0)
        if sim.stopping:  # the last program just ended: not one more step, so every run ends alike
            return
        live = [s for s in sim.sessions if s.robot is not None and not s.closed]
        now = time.perf_counter()
        waiting_for = [s for s in live if s.computing(now)]
        if waiting_for or sim.expected_programs:
            sim.wait(IDLE_WAIT)  # a program is computing: wait for its next call
            return
        boundary = sim.time_us + sim.step_us
        best = None
        for session in live:
            waiting = [(r, p) for r, p in session.pending if not session.held(r)]
            if session.next_queue() and not any(isinstance(p, Deferred) for _, p in waiting):
                key = (session.local_time_us, session.robot.id)
            else:
                wake = min((p.wake_us for _, p in waiting if p.wake_us is not None), default=None)
                if wake is None:
                    continue
                key = (max(wake, sim.time_us), session.robot.id)
            if best is None or key < best[0]:
                best = (key, session)
        if best is None or best[0][0] >= boundary:
            self._step_while_quiet(None if best is None else best[0][0])
            return
        (at_us, _), session = best
        if session.next_queue():
            sim.requests.flush_output(session)
            sim.requests.take(session, at_us)
        elif not sim.requests.wake_session(session, at_us):
            sim.wait(IDLE_WAIT)  # its reply is still being made (a camera image): wait for it, not time

    def _step_while_quiet(self, due_us: int | None) -> None:
        """Every program waits, for a reply or with a request at `due_us` or later (None: no request
        or timed wait is due). Step until the step that would pass `due_us`, a step that answers a
        waiting call (VWWait done: that program goes on), an action from another thread (a viewer
        command is carried out at the next step boundary), the run's end or QUIET_STEPS steps.
        Meanwhile no program can send anything (each waits for a reply), so looking at the sockets
        between these steps, as every round does, would find nothing."""
        sim = self.sim
        answered = sim.requests.answered_later
        for _ in range(QUIET_STEPS):
            sim.step()
            if sim.requests.answered_later != answered or sim.stopping or not sim.inbox.empty() or sim.clock.paused:
                return
            if due_us is not None and due_us < sim.time_us + sim.step_us:
                return
            if sim.until_us is not None and sim.time_us >= sim.until_us:
                return

    def arrived(self, session: Session) -> None:
        session.note_request(time.perf_counter())  # what Session.blocked goes by

    def queue(self, request: Request) -> None:
        request.session.enqueue(request)  # taken in (time, robot id) order by round

    def answer(self, request: Request, frame: bytes) -> None:
        """The program's clock goes on by the call's cost; the reply leaves at once."""
        request.session.local_time_us = request.time_us + self.sim.call_cost_us(request.op)
        self.sim.requests.send(request.session, frame)

    def defer(self, request: Request, deferred: Deferred) -> None:
        """Time waits for a reply made on another thread at exactly request time + cost (round), so
        it comes at the same simulation time in every run."""
        deferred.wake_us = request.time_us + self.sim.call_cost_us(request.op)
        request.session.local_time_us = request.time_us

    def holds(self, session: Session, request: Request, pending) -> bool:
        """While timer callbacks run, the main thread's replies are held; no callback runs while the
        main thread waits in a call that holds the library's timer lock."""
        return session.held(request) or pending.background and session.timers_locked()

    def answered(self, session: Session, pending) -> None:
        if pending.background:  # the timer thread's wait: its callbacks run now, alone
            session.timer_running = True

    def woke(self, session: Session) -> None:
        session.woke(time.perf_counter())

    def several_threads(self, session: Session) -> None:
        assert session.robot is not None  # asked only once the handshake has bound a robot
        log.warning(
            "robot %d (%s): RoBIOS calls come from more than one thread of the program; their "
            "order follows the operating system's scheduling, so this deterministic run may not "
            "repeat exactly (docs/running.md#time)",
            session.robot.id,
            session.program or "program",
        )

    def clear(self) -> None:
        """Nothing is kept outside the sessions."""


def schedule_for(sim):
    """The run's schedule, for the life of its clock."""
    return LockstepSchedule(sim) if sim.clock.deterministic else RealtimeSchedule(sim)
