"""Programs' requests on the simulation thread: delivery, the handshake, carrying a request out and
answering it, replies that come later (blocking calls, camera images), and a program's end.

What differs between the clock modes (when a request is taken, when its reply leaves) is the
run's schedule's (core/schedules.py): this module asks `sim.timing` and never looks at the mode.
Every answered call that reaches the robot's hardware or the world takes the call time of
simulation time (Simulation.call_cost_us); deterministic timers' callbacks run alone and their
calls are served first (Session.enqueue, Session.held)."""

from __future__ import annotations

import logging
import reprlib
import secrets
import struct
import traceback

from eyesim import calls
from eyesim.net import program_token
from eyesim.net.program_server import version_refusal
from eyesim.net.session import Deferred, Pending, Request, Session
from eyesim.protocol import encode_error, encode_message, generated as g

log = logging.getLogger("eyesim")


class Requests:
    """The request side of a Simulation (`sim.requests`); its state that other parts read (sessions,
    expected programs, the program token, request observers) stays on the Simulation."""

    def __init__(self, sim):
        self.sim = sim
        self.answered_later = 0  # pending calls answered so far (a step that answers one ends a quiet stretch)

    # -- program connections (called by sim.network on the simulation thread) -------------------
    def connected(self, session: Session) -> None:
        session.local_time_us = self.sim.time_us
        self.sim.sessions.append(session)

    def deliver(self, request: Request) -> None:
        """A request read from a program's socket, queued by the schedule; the handshake, and anything
        sent before it, is answered at once."""
        session = request.session
        if session.closed:
            return
        timing = self.sim.timing
        timing.arrived(session)
        if request.op.code == g.OP_HELLO or session.robot is None:
            request.time_us = max(self.sim.time_us, session.local_time_us)
            self.execute(request)
            return
        timing.queue(request)

    def take(self, session: Session, at_us: int) -> None:
        """Carry out the program's next queued request at simulation time `at_us`."""
        request = session.next_queue().popleft()
        request.time_us = at_us
        self.execute(request)
        session.connection.resume()  # room in its queue again, unless the call now waits (pending)

    def drop(self, session: Session) -> None:
        """A program's connection ended (or is ended): forget it; the run may be over."""
        self.flush_output(session)
        session.closed = True
        for _, pending in session.pending:
            pending.cancel()
        session.pending.clear()
        session.queued.clear()
        session.timer_queued.clear()
        sim = self.sim
        if session in sim.sessions:
            sim.sessions.remove(session)
            log.info("%s disconnected", session.name)
            if session.pid:
                sim.disconnected_pids.add(session.pid)
        sim.check_programs_done()

    def disconnect_all(self) -> None:
        """Disconnect every program and forget the ones expected; the port stays open for new ones."""
        for session in list(self.sim.sessions):
            session.connection.close()
            self.drop(session)
        self.sim.expected_programs.clear()
        self.sim.timing.clear()

    def flush_output(self, session: Session) -> None:
        """Pass on what the program wrote so far (programs/program_output.py)."""
        output = self.sim.program_outputs.get(session.pid) if session.pid else None
        if output is not None:
            output.flush()

    # -- carrying a request out ------------------------------------------------------------------
    def execute(self, request: Request) -> None:
        session = request.session
        op = request.op
        try:
            if op.code == g.OP_HELLO:
                result = self._hello(request)
            elif op.code == g.OP_THREADS and session.robot is not None:
                result = self._threads(session)
            elif session.robot is None:
                raise calls.CallError("the first request must be the HELLO handshake", g.ERR_NO_HANDSHAKE)
            else:
                problem = op.ranges and op.out_of_range(request.args)  # protocol.json's ranges, before any work
                if problem:
                    raise calls.CallError(problem, g.ERR_BAD_ARGUMENT)
                result = calls.HANDLERS[op.code](self.sim, session.robot, request)
        except calls.CallError as error:
            self.sim.timing.answer(request, encode_error(op.code, request.request_id, error.code, str(error)))
            if error.code == g.ERR_BAD_TOKEN:  # no second guess on this connection
                session.connection.close(flush=True)
            return
        except Exception:  # a fault stays with its call: the program gets an error, everyone else goes on
            log.error("handler for %s from %s failed:\n%s", op.name, session.name, traceback.format_exc())
            self.sim.timing.answer(
                request,
                encode_error(
                    op.code, request.request_id, g.ERR_BAD_ARGUMENT, "internal simulator error (see the simulator log)"
                ),
            )
            return
        if isinstance(result, Deferred):
            self.sim.timing.defer(request, result)
            session.pending.append((request, result))
            result.work.when_done(lambda: self.sim.call(lambda sim: sim.requests.wake_pending()))
            return
        if isinstance(result, Pending):
            if result.background:  # the timer thread's wait is looked at first (wake_session)
                session.pending.insert(0, (request, result))
            else:
                session.pending.append((request, result))
            session.local_time_us = request.time_us
            if result.background and session.timer_running:  # the callbacks are done: the rest goes on
                session.timer_running = False
                self.wake_session(session, self.sim.time_us)
            return
        self.sim.timing.answer(request, self._reply_frame(request, result))
        for observer in self.sim.request_observers:
            observer(session.robot, request, result)

    def _reply_frame(self, request: Request, values: tuple) -> bytes:
        """The encoded reply; a value that does not fit its field becomes an error reply, never a
        failure of the simulation thread."""
        try:
            return encode_message(request.op.code, g.KIND_REPLY, request.request_id, values)
        except (struct.error, OverflowError, TypeError, ValueError) as error:
            log.error(
                "reply to %s from %s does not encode (%s): %r", request.op.name, request.session.name, error, values
            )
            return encode_error(
                request.op.code,
                request.request_id,
                g.ERR_BAD_ARGUMENT,
                "the result does not fit the reply (a value out of range)",
            )

    def _deferred_frame(self, request: Request, deferred: Deferred) -> bytes:
        """The reply a Deferred made; an error reply if making it failed (logged here, once)."""
        if deferred.work.error is None:
            return deferred.work.result[1]
        log.error("handler for %s from %s failed:\n%s", request.op.name, request.session.name, deferred.work.error)
        return encode_error(
            request.op.code, request.request_id, g.ERR_BAD_ARGUMENT, "internal simulator error (see the simulator log)"
        )

    def send(self, session: Session, frame: bytes) -> None:
        if not session.closed:
            session.connection.send(frame)

    # -- the handshake ---------------------------------------------------------------------------
    def _hello(self, request: Request) -> tuple:
        version, selector, program, pid, token = request.args
        session = request.session
        sim = self.sim
        if version != g.VERSION:
            raise calls.CallError(version_refusal(version), g.ERR_VERSION)
        if session.robot is not None:
            raise calls.CallError("handshake sent twice", g.ERR_BAD_PAYLOAD)
        if sim.program_token is not None and not secrets.compare_digest(token.encode(), sim.program_token.encode()):
            sim.network.warnings.warn(
                "refused: a wrong or missing program token",
                "refused a program from %s (%s, pid %d): %s program token",
                session.peer,
                reprlib.repr(program),
                pid,
                "wrong" if token else "no",
            )
            raise calls.CallError(program_token.refusal(token, sim.program_token_file), g.ERR_BAD_TOKEN)
        robot = self._choose_robot(selector)
        session.robot, session.program, session.pid = robot, program, pid
        for component in robot.components:
            component.program_started()
        session.local_time_us = sim.time_us
        sim.expected_programs.discard(robot.id)
        log.info("%s connected", session.name)
        return (g.VERSION, robot.id, robot.name)

    def _threads(self, session: Session) -> tuple:
        """The library says a second thread of the program makes calls (THREADS, sent once, before
        that thread's first call): from now on time goes on only while both wait (Session.blocked),
        even if the second thread's first call arrives while the main thread computes."""
        session.threads_seen = max(session.threads_seen, 2)
        self.sim.timing.several_threads(session)
        return (0,)

    def _choose_robot(self, selector: str):
        robots = self.sim.robots
        taken = {s.robot.id for s in self.sim.sessions if s.robot is not None and not s.closed}
        names = ", ".join(f"{r.id} {r.name}" for r in robots) or "none"
        if not robots:
            raise calls.CallError("the scene has no robots", g.ERR_NO_ROBOT)
        if selector == "":
            free = [r for r in robots if r.id not in taken]
            if not free:
                raise calls.CallError(f"every robot already runs a program (robots: {names})", g.ERR_NO_ROBOT)
            return free[0]
        if selector.isascii() and selector.isdigit():  # not '²', which isdigit() but int() refuses
            robot = self.sim.robot_by_id(int(selector)) if len(selector) <= 9 else None
            candidates = [robot] if robot else []
        else:
            candidates = [r for r in robots if r.name.lower() == selector.lower()]
        if not candidates:
            raise calls.CallError(f"no robot {reprlib.repr(selector)} in the scene (robots: {names})", g.ERR_NO_ROBOT)
        free = [r for r in candidates if r.id not in taken]
        if not free:
            raise calls.CallError(f"robot {selector!r} already runs a program", g.ERR_NO_ROBOT)
        return free[0]

    # -- replies that come later -----------------------------------------------------------------
    def wake_pending(self) -> None:
        for session in self.sim.sessions:
            if session.pending:
                self.wake_session(session, self.sim.time_us)

    def wake_session(self, session: Session, at_us: int) -> bool:
        """Complete the session's pending replies whose condition holds at time `at_us`; whether any did.
        The timer thread's wait, kept first, is looked at first; the schedule may hold a reply back (deterministic timers'
        callbacks run alone, Session.held)."""
        timing = self.sim.timing
        still = []
        for request, pending in session.pending:
            values = None if timing.holds(session, request, pending) else pending.poll(at_us)
            if values is None:
                still.append((request, pending))
                continue
            session.local_time_us = max(session.local_time_us, at_us)
            if not isinstance(pending, Deferred):
                self.send(session, self._reply_frame(request, values))
                timing.answered(session, pending)
                continue
            self.send(session, self._deferred_frame(request, pending))
            pending.answered()
            timing.answered(session, pending)
            if pending.work.error is None:
                for observer in self.sim.request_observers:
                    observer(session.robot, request, values)
        answered = len(still) < len(session.pending)
        session.pending = still
        if answered:
            self.answered_later += 1
            timing.woke(session)
            if not session.closed:
                session.connection.resume()  # room for requests it holds back (program_server.MAX_QUEUED)
        return answered
