"""RoBIOS radio group: messages between robots' programs, in order per sender (ids = robot ids)."""

from eyesim.calls.errors import CallError, require
from eyesim.net.session import Pending
from eyesim.protocol import generated as g
from eyesim.robot.components.radio import MAX_WAITING, Radio


def _radio(robot) -> Radio:
    return require(robot.component(Radio), robot, "radio")


def _switched_on(robot, request) -> Radio:
    radio = _radio(robot)
    if not radio.on or radio.owner is not request.session:
        raise CallError("the radio is off; call RADIOInit first", g.ERR_NOT_SUPPORTED)
    return radio


def radio_init(sim, robot, request):
    _radio(robot).owner = request.session
    return (0,)


def radio_get_id(sim, robot, request):
    return (robot.id,)


def radio_send(sim, robot, request):
    destination, message = request.args
    _switched_on(robot, request)
    target = sim.robot_by_id(destination)
    if target is None or target.component(Radio) is None:
        ids = [r.id for r in sim.robots if r.component(Radio) is not None]
        raise CallError(f"no robot {destination} to send to (robot ids: {ids})")
    if not target.component(Radio).deliver(robot.id, bytes(message)):
        raise CallError(f"robot {destination} has {MAX_WAITING} unread messages; it takes no more")
    return (0,)


def radio_receive(sim, robot, request):
    radio = _switched_on(robot, request)
    message = radio.take()
    if message is not None:
        return message
    return Pending(lambda at_us: radio.take())


def radio_check(sim, robot, request):
    radio = _switched_on(robot, request)
    return (1 if radio.inbox else 0,)


def radio_status(sim, robot, request):
    return ([r.id for r in sim.robots if r.component(Radio) is not None and r.component(Radio).on],)


def radio_release(sim, robot, request):
    radio = _radio(robot)
    if radio.owner is request.session:
        radio.owner = None
    return (0,)


HANDLERS = {
    "RADIO_INIT": radio_init,
    "RADIO_GET_ID": radio_get_id,
    "RADIO_SEND": radio_send,
    "RADIO_RECEIVE": radio_receive,
    "RADIO_CHECK": radio_check,
    "RADIO_STATUS": radio_status,
    "RADIO_RELEASE": radio_release,
}
