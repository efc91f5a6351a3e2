"""RoBIOS IR remote group: codes from the viewer's remote, the keyboard or a script (IRTVRead and
IRTVFlush only call the receiver: protocol.json's "calls")."""

from eyesim.calls.errors import component_of
from eyesim.net.session import Pending
from eyesim.robot.components.irtv import IrReceiver


def _receiver(robot) -> IrReceiver:
    return component_of(robot, IrReceiver)


def irtv_get(sim, robot, request):
    """Blocks until a code arrives."""
    receiver = _receiver(robot)
    code = receiver.take()
    if code:
        return (code,)
    return Pending(lambda at_us: (receiver.take(),) if receiver.codes else None)


def irtv_get_status(sim, robot, request):
    _receiver(robot)
    return (1,)  # the simulated receiver is always on


HANDLERS = {"IRTV_GET": irtv_get, "IRTV_GET_STATUS": irtv_get_status}
