"""RoBIOS system group: waiting and counting in simulation time (milliseconds), and the machine's identity."""

from eyesim.commands.errors import CommandError
from eyesim.net.session import Pending
from eyesim.scene.drives import drive_of


def os_wait(sim, robot, request):
    (ms,) = request.args
    if ms < 0:
        raise CommandError(f"negative time {ms} ms")
    wake_us = request.time_us + ms * 1000
    return Pending.until(wake_us, (0,))


def os_sleep(sim, robot, request):
    """The program's sleep/usleep/nanosleep (rerouted by the C library) and Python's time.sleep: a wait
    in simulation time like OSWait, to the microsecond (rounded up, so that any sleep lets time go on)."""
    seconds, nanoseconds = request.args
    if nanoseconds >= 1_000_000_000:
        raise CommandError(f"sleep: {nanoseconds} nanoseconds is not below one second")
    return Pending.until(request.time_us + seconds * 1_000_000 + -(-nanoseconds // 1000), (0,))


def os_get_count(sim, robot, request):
    return (request.time_us // 1000,)


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
