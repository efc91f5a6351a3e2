"""RoBIOS IR remote group: codes from the viewer's remote, the keyboard or a script."""

from eyesim.commands.errors import require
from eyesim.net.session import Pending
from eyesim.robot.components.irtv import IrReceiver


def _receiver(robot) -> IrReceiver:
    return require(robot.component(IrReceiver), robot, "IR receiver")


def irtv_get(sim, robot, request):
    """Blocks until a code arrives."""
    receiver = _receiver(robot)
    code = receiver.take()
    if code:
        return (code,)
    return Pending(lambda at_us: (receiver.take(),) if receiver.codes else None)


def irtv_read(sim, robot, request):
    return (_receiver(robot).take(),)


def irtv_flush(sim, robot, request):
    _receiver(robot).flush()
    return (0,)


def irtv_get_status(sim, robot, request):
    _receiver(robot)
    return (1,)  # the simulated receiver is always on


HANDLERS = {"IRTV_GET": irtv_get, "IRTV_READ": irtv_read, "IRTV_FLUSH": irtv_flush,
            "IRTV_GET_STATUS": irtv_get_status}
