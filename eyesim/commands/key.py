"""RoBIOS key group: soft keys pressed in the viewer or by a script."""

from eyesim.commands.errors import require
from eyesim.robot.components.keys import Keys
from eyesim.session import Pending


def key_get(sim, robot, request):
    """Blocks until a key is pressed."""
    keys = require(robot.component(Keys), robot, "keys")
    key = keys.take()
    if key:
        return (key,)

    def poll(at_us):
        pressed = keys.take()
        return (pressed,) if pressed else None

    return Pending(poll)


def key_read(sim, robot, request):
    return (require(robot.component(Keys), robot, "keys").take(),)


HANDLERS = {"KEY_GET": key_get, "KEY_READ": key_read}
