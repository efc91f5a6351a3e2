"""RoBIOS timer group: OSAttachTimer/OSDetachTimer, and the wait of the library's timer thread.

The simulator keeps each timer's due time in simulation time. The C library runs one timer thread
that calls TIMER_WAIT and runs the callbacks of the timers its reply names, then waits again. In
deterministic mode time goes on only while both that thread and the main thread wait in a call
(session.Session.blocked): not while the main thread computes, nor while callbacks run."""

from eyesim.calls.errors import checked_arguments, require
from eyesim.net.session import Pending
from eyesim.robot.components.timers import ProgramTimers


def _timers(robot) -> ProgramTimers:
    return require(robot.component(ProgramTimers), robot, "timers")


class TimerWait(Pending):
    """Completes when one of the program's timers is due. Its wake time is looked up each time,
    since a timer attached while it waits may be due sooner."""

    background = True

    def __init__(self, timers: ProgramTimers, session):  # no Pending.__init__: wake_us is computed
        self.timers, self.session = timers, session

    @property  # read-only here: the engine never sets a timer wait's wake time
    def wake_us(self):  # type: ignore[override]
        return self.timers.next_due_us(self.session)

    def poll(self, at_us):
        due = self.timers.take_due(self.session, at_us)
        return (due,) if due else None


def timer_attach(sim, robot, request):
    (period_ms,) = request.args
    with checked_arguments():
        handle = _timers(robot).attach(request.session, period_ms, request.time_us)
    if not request.session.helper_threads:  # the library starts its timer thread now
        request.session.helper_threads = 1
        request.session.timer_starting = sim.clock.deterministic
    return (handle,)


def timer_detach(sim, robot, request):
    (handle,) = request.args
    with checked_arguments():
        _timers(robot).detach(request.session, handle)
    return (0,)


def timer_wait(sim, robot, request):
    wait = TimerWait(_timers(robot), request.session)
    reply = wait.poll(request.time_us)
    if reply is None:
        return wait
    request.session.timer_running = sim.clock.deterministic  # callbacks run now (Session.enqueue)
    return reply


HANDLERS = {"TIMER_ATTACH": timer_attach, "TIMER_DETACH": timer_detach, "TIMER_WAIT": timer_wait}
