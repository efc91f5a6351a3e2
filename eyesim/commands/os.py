"""RoBIOS system/timer group: waiting and counting in simulation time (milliseconds)."""

from eyesim.commands.errors import CommandError
from eyesim.session import Pending


def os_wait(sim, robot, request):
    (ms,) = request.args
    if ms < 0:
        raise CommandError(f"OSWait: negative time {ms} ms")
    wake_us = request.time_us + ms * 1000
    return Pending.until(wake_us, (0,))


def os_get_count(sim, robot, request):
    return (request.time_us // 1000,)


HANDLERS = {"OS_WAIT": os_wait, "OS_GET_COUNT": os_get_count}
