"""RoBIOS system group: waiting and counting in simulation time (milliseconds), and the machine's identity."""

from eyesim.calls.errors import CallError
from eyesim.net.session import Pending
from eyesim.scene.drives import drive_of


def os_wait(sim, robot, request):
    (ms,) = request.args
    if ms < 0:
        raise CallError(f"negative time {ms} ms")
    wake_us = request.time_us + ms * 1000
    return Pending.until(wake_us, (0,))


def os_sleep(sim, robot, request):
    """The program's sleep/usleep/nanosleep (rerouted by the C library) and Python's time.sleep: a wait
    in simulation time like OSWait, to the microsecond (rounded up, so that any sleep lets time go on)."""
    seconds, nanoseconds = request.args
    if nanoseconds >= 1_000_000_000:
        raise CallError(f"sleep: {nanoseconds} nanoseconds is not below one second")
    return Pending.until(request.time_us + seconds * 1_000_000 + -(-nanoseconds // 1000), (0,))


def os_get_count(sim, robot, request):
    """OSGetCount and OSGetTime: milliseconds of simulation time. Reading the clock is something the
    EyeBot does itself, in microseconds (a local call), so in deterministic mode, where time stands
    still while a program computes, a program that polls the clock waiting for time to pass would
    spin for ever in a millisecond. So there a read within the millisecond of the program's
    previous read waits for the next one: the clock never shows the same value twice in a row,
    and a polling loop sees time pass at 1 ms a turn (docs/protocol.md#what-a-call-costs)."""
    ms = request.time_us // 1000
    session = request.session
    if sim.clock.deterministic:
        if ms <= session.last_clock_ms:
            ms = session.last_clock_ms + 1
            session.last_clock_ms = ms
            return Pending.until(ms * 1000, (ms,))
        session.last_clock_ms = ms
    return (ms,)


def os_machine_name(sim, robot, request):
    return (robot.name,)


def os_machine_id(sim, robot, request):
    return (robot.id,)


def os_machine_type(sim, robot, request):
    """What the robot's drive declares: a manipulator on a fixed base is a PLATFORM, everything that
    moves about a VEHICLE (no walking robots here)."""
    return (int(drive_of(robot.type).machine_type),)


HANDLERS = {
    "OS_WAIT": os_wait,
    "OS_SLEEP": os_sleep,
    "OS_GET_COUNT": os_get_count,
    "OS_MACHINE_NAME": os_machine_name,
    "OS_MACHINE_ID": os_machine_id,
    "OS_MACHINE_TYPE": os_machine_type,
}
