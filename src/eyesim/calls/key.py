"""RoBIOS key group: soft keys and touches on the LCD, from the viewer or a script (KEYRead only
takes a press: protocol.json's "calls")."""

from eyesim.calls.errors import CallError, component_of
from eyesim.net.session import Pending
from eyesim.robot.components.keys import KEYS, Keys


def _keys(robot) -> Keys:
    return component_of(robot, Keys)


def _wait_for(take):
    """The reply now if `take()` has one, else a Pending that takes it when it comes."""
    reply = take()
    if reply is not None:
        return reply
    return Pending(lambda at_us: take())


def key_get(sim, robot, request):
    """Blocks until a key is pressed."""
    keys = _keys(robot)
    return _wait_for(lambda: (keys.take(),) if keys.presses else None)


def key_wait(sim, robot, request):
    """Blocks until a key in the mask is pressed; presses of other keys are used up meanwhile."""
    (mask,) = request.args
    keys = _keys(robot)
    if not mask & sum(KEYS):
        raise CallError(f"mask {mask:#x} contains none of KEY1..KEY4, so no key could end the wait")

    def take():
        key = keys.take_matching(mask)
        return (key,) if key else None

    return _wait_for(take)


def key_get_xy(sim, robot, request):
    """Blocks until the LCD is touched."""
    keys = _keys(robot)

    def take():
        point = keys.take_touch()
        return (0, *point) if point else None

    return _wait_for(take)


def key_read_xy(sim, robot, request):
    point = _keys(robot).take_touch()
    return (0, *point) if point else (1, 0, 0)


HANDLERS = {
    "KEY_GET": key_get,
    "KEY_WAIT": key_wait,
    "KEY_GET_XY": key_get_xy,
    "KEY_READ_XY": key_read_xy,
}
